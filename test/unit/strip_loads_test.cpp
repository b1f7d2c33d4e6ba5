// The strip's loads (docs/theory.md, (A7)-(A9)) against the typical section's generalised loads (A4), which
// PetersSection.* checks against Theodorsen: a strip with chord along +y and lift along +z in a stream U along
// +y, pitched by alpha and plunging by h, must carry the lift -Q_h and the moment Q_alpha of ThinAirfoilLoads
// to first order in the motion; with a trailing-edge flap (A10), also the hinge moment Q_delta.

#include <gtest/gtest.h>

#include <vector>

#include "flexmbd/aero/beam_strip_aero.hpp"
#include "flexmbd/aero/thin_airfoil_loads.hpp"

namespace flexmbd {
namespace strip_loads_test {

constexpr double kRho = 1.225, kU = 30.0, kB = 0.5, kA = -0.3;
// Motions of relative size 1e-6 (angles, and rates per U/b): the strip's exact kinematics (cos alpha, the
// rotated normal) differ from the linear theory's by terms 1e-6 times smaller; 1e-5 of the largest load leaves
// room for the sum of several.
constexpr double kSmall = 1.0e-6, kTolerance = 1.0e-5;

constexpr double kHinge = 0.5;

struct Comparison {
  Vec3 strip, section;  // (lift, moment, hinge moment) per unit span
};

// With `flap`, the strip's flap node (node 1) stands turned by alpha + delta, moving at the pitch's rates plus
// the flap's.
Comparison Compare(int states, bool flap) {
  AeroStripSpec spec;
  spec.name = "test";
  spec.semichord = kB;
  spec.a = kA;
  spec.inflow_states = states;
  spec.flap.c = kHinge;
  AeroFlowSpec flow;
  flow.free_stream = Vec3(0.0, kU, 0.0);
  flow.density = kRho;
  StripFlap strip_flap;
  if (flap) {
    strip_flap.node = 1;
    strip_flap.node_unknown = 6;
    strip_flap.fraction = 1.0;
  }
  BeamStripAero strip(spec, flow, 0, 0, 1.0, 12, strip_flap);
  strip.set_first_state(0);
  // h down, alpha nose up about e = n x c = -x, delta trailing edge down about e, and their rates; the inflow
  // states of a wake that lags.
  const double alpha = kSmall, alpha_rate = 3 * kSmall * kU / kB, alpha_acc = 4 * kSmall * kU * kU / (kB * kB);
  const double h_rate = -2 * kSmall * kU, h_acc = 5 * kSmall * kU * kU / kB;
  const double delta = flap ? -2 * kSmall : 0.0, delta_rate = flap ? 6 * kSmall * kU / kB : 0.0;
  const double delta_acc = flap ? -7 * kSmall * kU * kU / (kB * kB) : 0.0;
  const Vec3 e = -Vec3::UnitX();
  NodeState pitched;
  pitched.R = Exp(alpha * e);
  NodeStep node = MakeNodeStep(pitched, Vec6::Zero(), AnalysisMode::kEndPoint);
  node.v_f = -h_rate * Vec3::UnitZ();
  node.vdot_f = -h_acc * Vec3::UnitZ();
  node.w_f = alpha_rate * e;
  node.wdot_f = alpha_acc * e;
  NodeState turned;
  turned.R = Exp((alpha + delta) * e);
  NodeStep flap_node = MakeNodeStep(turned, Vec6::Zero(), AnalysisMode::kEndPoint);
  flap_node.w_f = (alpha_rate + delta_rate) * e;
  flap_node.wdot_f = (alpha_acc + delta_acc) * e;
  const std::vector<NodeStep> nodes = {node, flap_node};
  std::vector<ElementStateStep> inflow(states);
  for (int k = 0; k < states; ++k) inflow[k].value = kSmall * kU * (0.5 - 0.2 * k);
  StepContext ctx;
  ctx.mode = AnalysisMode::kEndPoint;
  ctx.nodes = &nodes;
  ctx.element_states = &inflow;
  Comparison out;
  out.strip = strip.StripLoads(ctx);
  // lambda0 of (A9) from the same states: (1/2) bbar^T mu + lag0 w34.
  const ThinAirfoilLoads loads(kB, kA, kHinge);
  double lambda0 = 0.0;
  if (states > 0) {
    const PetersInflow peters(states);
    const Eigen::VectorXd lag = peters.A.partialPivLu().solve(peters.c);
    const double w34 = loads.ew.dot(Vec3(h_rate, alpha_rate, delta_rate)) + kU * loads.eg.dot(Vec3(0, alpha, delta));
    for (int k = 0; k < states; ++k) lambda0 += 0.5 * peters.b[k] * (inflow[k].value + lag[k] * w34);
  }
  const Vec3 Q = loads.Forces(kRho, kU, Vec3(0.0, alpha, delta), Vec3(h_rate, alpha_rate, delta_rate),
                              Vec3(h_acc, alpha_acc, delta_acc), lambda0);
  out.section = Vec3(-Q[0], Q[1], flap ? Q[2] : 0.0);
  return out;
}

void ExpectEqual(const Comparison& c) {
  EXPECT_LT((c.strip - c.section).cwiseAbs().maxCoeff(), kTolerance * c.section.cwiseAbs().maxCoeff())
      << "strip " << c.strip.transpose() << ", section " << c.section.transpose();
}

TEST(StripLoads, QuasiSteadySmallMotionMatchesTheTypicalSection) { ExpectEqual(Compare(0, false)); }

TEST(StripLoads, WakeInflowMatchesTheTypicalSection) { ExpectEqual(Compare(6, false)); }

TEST(StripLoads, QuasiSteadyFlapMatchesTheTypicalSectionWithItsHingeMoment) {
  const Comparison c = Compare(0, true);
  ExpectEqual(c);
  // The hinge moment, an order smaller than the moment, to the same relative accuracy on its own.
  EXPECT_NEAR(c.strip[2], c.section[2], kTolerance * std::abs(c.section[2]));
}

TEST(StripLoads, FlapInWakeInflowMatchesTheTypicalSectionWithItsHingeMoment) {
  const Comparison c = Compare(6, true);
  ExpectEqual(c);
  EXPECT_NEAR(c.strip[2], c.section[2], kTolerance * std::abs(c.section[2]));
}

// A flat plate in air from its trailing edge (reverse flow, docs/theory.md (A12)), described twice: strip A with
// chord axis +y and its beam axis a b aft of mid-chord, which sees the air from behind (u < 0), and strip B with
// chord axis -y and its beam axis at -a b (the same point), which sees the same air from its leading edge. Both are
// the same plate in the same air, turned and moving in every direction with the same inflow states: their lift
// along +z and their moments about +x (A's pitch axis is -x, B's +x) agree to round-off.
Vec3 PlateLiftAndMomentAboutX(const Vec3& chord_axis, double a, int states) {
  AeroStripSpec spec;
  spec.name = "plate";
  spec.semichord = kB;
  spec.a = a;
  spec.chord_axis = chord_axis;
  spec.inflow_states = states;
  AeroFlowSpec flow;
  flow.free_stream = Vec3(0.0, -kU, 2.0);
  flow.density = kRho;
  BeamStripAero strip(spec, flow, 0, 0, 1.0, 6, StripFlap());
  strip.set_first_state(0);
  NodeState turned;
  turned.R = Exp(Vec3(0.05, -0.02, 0.03));
  NodeStep node = MakeNodeStep(turned, Vec6::Zero(), AnalysisMode::kEndPoint);
  node.v_f = Vec3(0.4, 1.0, -0.7);
  node.vdot_f = Vec3(3.0, -2.0, 5.0);
  node.w_f = Vec3(1.5, -0.4, 0.6);
  node.wdot_f = Vec3(-8.0, 2.0, 1.0);
  const std::vector<NodeStep> nodes = {node};
  std::vector<ElementStateStep> inflow(states);
  for (int k = 0; k < states; ++k) inflow[k].value = 0.3 - 0.1 * k;
  StepContext ctx;
  ctx.mode = AnalysisMode::kEndPoint;
  ctx.nodes = &nodes;
  ctx.element_states = &inflow;
  const Vec3 loads = strip.StripLoads(ctx);
  const Vec3 pitch_axis = spec.normal_axis.cross(chord_axis);
  return Vec3(loads[0], loads[1] * pitch_axis.x(), 0.0);
}

void ExpectReverseFlowIsTheMirroredPlate(int states) {
  const Vec3 reverse = PlateLiftAndMomentAboutX(Vec3::UnitY(), kA, states);
  const Vec3 forward = PlateLiftAndMomentAboutX(-Vec3::UnitY(), -kA, states);
  constexpr double kRoundOff = 1.0e-12;
  EXPECT_LT((reverse - forward).cwiseAbs().maxCoeff(), kRoundOff * forward.cwiseAbs().maxCoeff())
      << "reverse " << reverse.transpose() << ", mirrored forward " << forward.transpose();
  // The air crosses the plate upwards (its normal component relative to the plate about 4 m/s): lift up, whichever
  // edge the air meets first.
  EXPECT_GT(reverse[0], 0.0);
}

TEST(StripLoads, QuasiSteadyReverseFlowIsTheMirroredPlateInForwardFlow) { ExpectReverseFlowIsTheMirroredPlate(0); }

TEST(StripLoads, ReverseFlowWithWakeInflowIsTheMirroredPlateInForwardFlow) { ExpectReverseFlowIsTheMirroredPlate(4); }

}  // namespace strip_loads_test
}  // namespace flexmbd
