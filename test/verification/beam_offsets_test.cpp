// Section offsets of the geometrically exact beam (docs/theory.md, (B6), (B8)): centre of mass off the beam
// axis (coupled bending-torsion vibration) and shear centre off the axis (twist under a shear force).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "beam_cases.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace beam_offsets_test {

constexpr double kLength = 1.0, kEI = 100.0, kMass = 1.0;

TEST(BeamOffsets, ShearForceThroughTheAxisTwistsByForceTimesOffset) {
  // Shear centre at (y_s, z_s): a tip force F along y through the beam axis has the torque z_s F about the
  // shear centre, along z the torque -y_s F, so the tip twists by that torque times L / GJ (Saint-Venant,
  // e.g. Megson, Aircraft Structures, sec. 17.3). Linear check: tip slopes F L^2 / (2 EI) = 5e-5 bound the
  // geometric coupling of twist and bending to that fraction of the twist (measured 4e-6 and 6e-6); cubic
  // elements reproduce the linear twist exactly.
  constexpr double kGJ = 50.0, kForce = 0.01, ys = 0.02, zs = 0.03;
  constexpr double kRelativeTolerance = 1.0e-4;
  for (const Vec3& force : {Vec3(0, kForce, 0), Vec3(0, 0, kForce)}) {
    BeamSectionSpec section = test::Section(1.0e6, 1.0e6, kGJ, kEI, kMass, 1.0e-3, 1.0e-3);
    section.shear_center_offset = Eigen::Vector2d(ys, zs);
    ModelSpec spec = test::Cantilever(kLength, 4, 3, section);
    spec.loads.push_back(test::TipLoad(LoadSpec::Kind::kForce, force, kLength));
    spec.solver.analysis = SolverSpec::Analysis::kStatic;
    spec.solver.tol = 1.0e-10;
    const Model model = BuildModel(spec);
    Simulation simulation(model);
    simulation.Run([](const OutputSample&) {});
    const double twist = Log(simulation.state().nodes[model.beams()[0].nodes.back()].R).x();
    const double expected = (zs * force.y() - ys * force.z()) * kLength / kGJ;
    EXPECT_NEAR(twist / expected, 1.0, kRelativeTolerance) << force.transpose();
    RecordProperty(force.y() != 0 ? "twist_error_force_y" : "twist_error_force_z",
                   test::Figure(twist / expected - 1.0));
  }
}

// Uniform cantilever, Euler-Bernoulli bending w along z (stiffness EI) and Saint-Venant torsion theta (GJ),
// centre of mass at y = e: the section's mass point moves by w + e theta along z, so
//   EI w'''' + m (w'' + e theta)^.. = 0,   GJ theta'' = I_a theta^.. + m e w^..,   I_a = I_cg + m e^2
// (Banerjee, J. Sound Vib. 129 (1989) 263-270, with bending-torsion coupling by the mass offset only). With
// w, theta ~ f(x) sin(omega t), f'' = mu f, mu solves
//   EI GJ mu^3 + EI I_a omega^2 mu^2 - m GJ omega^2 mu - m I_cg omega^4 = 0,
// with one positive root and two negative ones, and theta = c(mu) w with c = (EI mu^2 - m omega^2) / (m e omega^2).
// The clamped-free conditions on the six solutions give det A(omega) = 0, found by a scan and bisection.
struct CoupledBeam {
  double EI, GJ, m, I_cg, e, L;

  double Cubic(double mu, double w2) const {
    const double Ia = I_cg + m * e * e;
    return EI * GJ * mu * mu * mu + EI * Ia * w2 * mu * mu - m * GJ * w2 * mu - m * I_cg * w2 * w2;
  }
  // The root of the cubic in (lo, hi), where its sign changes.
  double Root(double lo, double hi, double w2) const {
    const double sign_lo = Cubic(lo, w2) > 0 ? 1.0 : -1.0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (Cubic(mid, w2) > 0 ? 1.0 : -1.0) == sign_lo ? lo = mid : hi = mid;
    }
    return 0.5 * (lo + hi);
  }
  double Determinant(double omega) const {
    const double w2 = omega * omega, Ia = I_cg + m * e * e;
    const double split = -Ia * w2 / GJ, big = 1.0e8;
    const double roots[3] = {Root(0.0, big, w2), Root(split, 0.0, w2), Root(-big, split, w2)};
    Eigen::Matrix<double, 6, 6> A;
    int column = 0;
    for (double mu : roots) {
      const double c = (EI * mu * mu - m * w2) / (m * e * w2);
      const double k = std::sqrt(std::abs(mu));
      // f, f', f'', f''' at x for the two solutions of f'' = mu f.
      for (int pair = 0; pair < 2; ++pair) {
        auto derivatives = [&](double x) {
          Eigen::Vector4d d;
          if (mu > 0) {
            const double ch = std::cosh(k * x), sh = std::sinh(k * x);
            d = pair == 0 ? Eigen::Vector4d(ch, k * sh, k * k * ch, k * k * k * sh)
                          : Eigen::Vector4d(sh, k * ch, k * k * sh, k * k * k * ch);
          } else {
            const double co = std::cos(k * x), si = std::sin(k * x);
            d = pair == 0 ? Eigen::Vector4d(co, -k * si, -k * k * co, k * k * k * si)
                          : Eigen::Vector4d(si, k * co, -k * k * si, -k * k * k * co);
          }
          return d;
        };
        const Eigen::Vector4d root = derivatives(0.0), tip = derivatives(L);
        A.col(column++) << root[0], root[1], c * root[0], tip[2], tip[3], c * tip[1];
      }
    }
    return A.determinant();
  }
  // The lowest `count` natural frequencies [rad/s].
  std::vector<double> Frequencies(int count) const {
    std::vector<double> found;
    double previous = Determinant(1.0);
    for (double w = 1.0; found.size() < static_cast<size_t>(count); w += 0.25) {
      const double next = Determinant(w + 0.25);
      if ((previous > 0) != (next > 0)) {
        double lo = w, hi = w + 0.25;
        for (int i = 0; i < 60; ++i) {
          const double mid = 0.5 * (lo + hi);
          ((Determinant(mid) > 0) == (previous > 0) ? lo : hi) = mid;
        }
        found.push_back(0.5 * (lo + hi));
      }
      previous = next;
    }
    return found;
  }
};

TEST(BeamOffsets, CentreOfMassOffsetCouplesBendingAndTorsionAsTheExactSolution) {
  // Torsion tuned near the first bending frequency so the coupling moves both by tens of percent.
  const CoupledBeam exact{kEI, 10.0, kMass, 0.01, 0.1, kLength};
  const std::vector<double> omega = exact.Frequencies(3);
  // Uncoupled values: bending 1.8751^2 sqrt(EI / m L^4), 4.6941^2 ..., torsion (pi / 2 L) sqrt(GJ / I_a).
  const double uncoupled[] = {1.8751 * 1.8751 * 10.0, 4.6941 * 4.6941 * 10.0, M_PI / 2 * std::sqrt(10.0 / 0.02)};

  BeamSectionSpec section = test::Section(1.0e8, 1.0e8, 10.0, kEI, kMass, 0.01, 1.0e-7);
  section.cg_offset = Eigen::Vector2d(0.1, 0.0);
  const Model model = BuildModel(test::Cantilever(kLength, 10, 3, section));
  EigenOptions options;
  options.rigid_tolerance = 1.0e-12;
  const EigenResult result = EigenAnalysis(model, model.initial_state(), options);
  // 10 cubic elements with lumped mass: 1e-4 at most on the lowest uncoupled modes (BeamModes; measured here
  // 1.5e-6 at worst).
  constexpr double kTolerance = 1.0e-4;
  // An uncoupled model would miss every exact frequency by more than this.
  constexpr double kCouplingShift = 0.05;
  for (double w : omega) {
    double nearest = 1.0e300;
    for (const Mode& mode : result.modes) {
      if (!mode.rigid_body) nearest = std::min(nearest, std::abs(2 * M_PI * mode.frequency_hz / w - 1.0));
    }
    EXPECT_LT(nearest, kTolerance) << "exact coupled frequency " << w << " rad/s";
    RecordProperty("coupled_" + std::to_string(w) + "_rad_s_error", test::Figure(nearest));
    // The coupling matters: each exact frequency is far from every uncoupled one.
    for (double u : uncoupled) EXPECT_GT(std::abs(w / u - 1.0), kCouplingShift) << w << " vs uncoupled " << u;
  }
}

TEST(BeamOffsets, OffsetMassesAndShearCentreKeepTheEnergyIdentity) {
  // Energy-preserving scheme: E - E0 = W_ext over every step (docs/theory.md (T6)): the offset masses are rigid
  // bodies at their centres of mass, their fixed joints do no work, the offset stiffness is a quadratic energy.
  // A tip kick in y and z excites coupled bending and torsion.
  BeamSectionSpec section = test::Section(1.0e4, 1.0e4, 10.0, kEI, kMass, 0.01, 1.0e-3);
  section.cg_offset = Eigen::Vector2d(0.05, -0.03);
  section.shear_center_offset = Eigen::Vector2d(0.02, 0.01);
  ModelSpec spec = test::Cantilever(kLength, 2, 3, section);
  spec.loads.push_back(test::TipKick(Vec3(0, 5.0, 5.0), kLength, 0.05));
  spec.solver.integrator = SolverSpec::Integrator::kEnergyPreserving;
  spec.solver.adaptive = false;
  spec.solver.dt = 2.0e-3;
  spec.solver.t_end = 0.3;
  spec.solver.tol = 1.0e-10;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  double initial = 0, worst = 0, largest = 0;
  bool first = true;
  simulation.Run([&](const OutputSample& s) {
    if (first) initial = s.total(), first = false;
    worst = std::max(worst, std::abs(s.total() - initial - s.external_work));
    largest = std::max(largest, std::abs(s.total()));
  });
  ASSERT_GT(largest, 0.0);
  // The Newton tolerance (1e-10 relative per step) over 150 steps, as in BeamDynamics.
  constexpr double kEnergyTolerance = 1.0e-7;
  EXPECT_LT(worst / largest, kEnergyTolerance);
  RecordProperty("energy_balance_relative", test::Figure(worst / largest));
}

}  // namespace beam_offsets_test
}  // namespace flexmbd
