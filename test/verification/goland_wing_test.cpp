// The Goland wing (Goland 1945) from its own files (config/goland_wing/): structural frequencies, the flutter
// speed and frequency of strip theory, and the free motion after a gust just below and above flutter
// (docs/validation.md).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "peak_rate.hpp"
#include "runner_output.hpp"
#include "yaml_text.hpp"

namespace flexmbd {
namespace goland_wing_test {

const std::string kDir = std::string(FLEXMBD_SOURCE_DIR) + "/config/goland_wing/";

ModelSpec Case(const std::string& yaml) { return LoadModelSpec(kDir + "goland_wing.urdf", kDir + yaml); }

// At zero angle of attack the strips neither damp nor drive the in-plane (chordwise) motion: those roots stay on
// the imaginary axis, their real parts round-off below 1e-6 |s|. A root counts only when its real part is larger;
// near flutter this ignores the flutter root within 1e-6 x 70 rad/s = 7e-5 1/s of the axis, which moves the
// speed found by 2e-4 m/s (its real part changes by 0.4 1/s per m/s). Roots above 10% of the frequency scale (the
// beam's axial and shear roots, up to 1.2e5 Hz) have round-off real parts beyond that and are left out too
// (theory (E9)).
constexpr double kRoundOff = 1.0e-6, kResolved = 0.1;

// The least stable root (largest real part) at speed U with N inflow states, among the rigid-body and the
// undamped or unresolved roots left out above (real part > 0: unstable) [1/s].
std::complex<double> LeastStableRoot(double U, int states) {
  ModelSpec spec = Case("flutter_eigen.yaml");
  spec.aero_flow.free_stream = Vec3(0.0, U, 0.0);
  spec.aero_strips.at(0).inflow_states = states;
  const Model model = BuildModel(spec);
  const EigenResult result = EigenAnalysis(model, model.initial_state(), EigenOptions{});
  std::complex<double> worst(-1e300, 0.0);
  for (const Mode& mode : result.modes) {
    if (mode.rigid_body || std::abs(mode.eigenvalue.real()) < kRoundOff * std::abs(mode.eigenvalue) ||
        mode.frequency_hz > kResolved * result.frequency_scale_hz) {
      continue;
    }
    if (mode.eigenvalue.real() > worst.real()) worst = mode.eigenvalue;
  }
  return worst;
}

using test::ReadFile;

TEST(GolandWing, UncoupledFrequenciesMatchPublished) {
  // flexmbd_run on structure_uncoupled.yaml (centre of mass on the elastic axis). Published: first bending
  // 1.875^2 sqrt(EI / (m L^4)) = 49.5 rad/s and first torsion (pi/2) sqrt(GJ / I) / L = 87.1 rad/s, to three
  // figures: 0.2% covers their rounding (0.1%) and eight cubic elements with the lumped mass (B6).
  const std::string table = test::RunnerOutput("config/goland_wing/goland_wing.urdf",
                                               ReadFile(kDir + "structure_uncoupled.yaml"), "goland_modes");
  constexpr double kPublished[2] = {49.5, 87.1};
  constexpr double kRelative = 2.0e-3;
  for (int k = 0; k < 2; ++k) {
    const double omega = 2 * M_PI * test::TableFrequency(table, k + 1);
    std::printf("mode %d: %.3f rad/s\n", k + 1, omega);
    EXPECT_NEAR(omega, kPublished[k], kRelative * kPublished[k]) << table;
  }
}

TEST(GolandWing, ClampedWingHasNoRigidBodyModes) {
  // The wing is clamped at its root, so no root is a rigid-body motion. The root strip's inflow states are driven
  // by nothing (its node does not move), and their real roots, whose shapes hold no node motion, were taken as
  // rigid by the round-off tests of (E5) (one at 136 m/s, six at 50 m/s): they are roots of the states' own
  // equations and must be listed as such. How much node motion round-off leaves in their shapes depends on the
  // last bits of the eigensolver (their roots lie within 1e-4 of the driven strips' alike roots, which mix in): at
  // 50 m/s one such shape moved its nodes by 2.5e-8 of its states on one machine and was taken as rigid. Speeds every
  // 10 m/s give the classification as many round-off patterns, and lower roots (46 inflow roots were rigid at 10 m/s
  // while the tests weighed the states' rows).
  for (double speed :
       {10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0, 90.0, 100.0, 110.0, 120.0, 130.0, 136.0, 150.0}) {
    ModelSpec spec = Case("flutter_eigen.yaml");
    spec.aero_flow.free_stream = Vec3(0.0, speed, 0.0);
    const Model model = BuildModel(spec);
    EigenOptions options;
    options.num_modes = 0;  // every root
    const EigenResult result = EigenAnalysis(model, model.initial_state(), options);
    EXPECT_EQ(result.num_rigid_body, 0) << speed << " m/s";
    int roots = 0;  // a pair counts twice, a real root once
    for (const Mode& mode : result.modes) roots += mode.eigenvalue.imag() > 0 ? 2 : 1;
    EXPECT_EQ(roots, 2 * result.num_dof + result.num_states) << speed << " m/s: every root listed";
  }
}

TEST(GolandWing, FlutterSpeedMatchesStripTheory) {
  // Published with Theodorsen's strip theory: 137.2 m/s at 70.7 rad/s (Goland 1945, as quoted by Patil, Hodges
  // and Cesnik 2001). Peters' six states follow Theodorsen's C(k) within about 1% at the flutter reduced
  // frequency k = w b / U = 0.47, the bisection stops within 0.01%, and the beam's discretisation is within 0.2%
  // (UncoupledFrequenciesMatchPublished): 2% covers them.
  constexpr double kSpeed = 137.2, kFrequency = 70.7, kRelative = 0.02;
  // Single eigen-analyses of flutter_eigen.yaml at 136.0 and 136.2 m/s give the 11.15 Hz mode damping ratios
  // +6.15e-4 and -3.04e-4: linearly, zero at 136.13 m/s. (This test's former bisection found 135.89 m/s: its least
  // stable root there was a round-off 1.21e5 Hz root, theory (E9).) The runner must agree within the 0.1% the issue
  // asks.
  constexpr double kOwnBisection = 136.13, kAgreement = 1.0e-3;
  const std::string output =
      test::RunnerOutput("config/goland_wing/goland_wing.urdf", ReadFile(kDir + "flutter_sweep.yaml"), "goland_sweep");
  const std::vector<test::Crossing> crossings = test::RunnerCrossings(output);
  // One flutter crossing in 120-150 m/s: no spurious one from a round-off root or a mode tracked wrongly.
  ASSERT_EQ(crossings.size(), 1u) << output;
  const test::Crossing& flutter = crossings.front();
  std::printf("runner: %s at %.6g m/s, %.4g Hz (%.3f rad/s)\n", flutter.kind.c_str(), flutter.speed,
              flutter.frequency_hz, 2 * M_PI * flutter.frequency_hz);
  EXPECT_EQ(flutter.kind, "flutter") << output;
  EXPECT_NEAR(flutter.speed, kOwnBisection, kAgreement * kOwnBisection) << output;
  EXPECT_NEAR(flutter.speed, kSpeed, kRelative * kSpeed) << output;
  EXPECT_NEAR(2 * M_PI * flutter.frequency_hz, kFrequency, kRelative * kFrequency) << output;
  // The least stable root on either side of the crossing, 0.1% away: stable below, growing above.
  EXPECT_LT(LeastStableRoot(flutter.speed * (1.0 - kAgreement), 6).real(), 0.0);
  EXPECT_GT(LeastStableRoot(flutter.speed * (1.0 + kAgreement), 6).real(), 0.0);
}

struct FreeMotion {
  double rate = 0;        // of the tip twist peaks [1/s]
  double eigen_rate = 0;  // real part of the least stable root at the same speed [1/s]
  double books = 0;       // largest |E - E0 + numerical - external| [J]
  double throughput = 0;  // largest |external work| [J]
};

// The motion after the gust pulse of `yaml`: the growth rate of the tip's twist over [t0, t_end].
FreeMotion FreeRun(const std::string& yaml, double t0) {
  const ModelSpec spec = Case(yaml);
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  std::vector<double> t, twist;
  FreeMotion run;
  double e0 = NAN;
  simulation.Run([&](const OutputSample& s) {
    t.push_back(s.t);
    twist.push_back(s.beam_stations.at(0).rotation.x());
    if (std::isnan(e0)) e0 = s.total();
    run.books =
        std::max(run.books, std::abs(s.total() - e0 + s.numerical_dissipation + s.dissipated - s.external_work));
    run.throughput = std::max(run.throughput, std::abs(s.external_work));
  });
  run.rate = test::PeakRate(t, twist, t0, spec.solver.t_end);
  run.eigen_rate = LeastStableRoot(spec.aero_flow.free_stream.y(), spec.aero_strips.at(0).inflow_states).real();
  return run;
}

// Energy books of the free runs: kinetic + strain + numerical dissipation - the air's work stays at its start
// value; the local error of the steps (error_tol 1e-4 relative per step) bounds what is left, against the energy
// the air moved.
constexpr double kBooks = 1.0e-2;

TEST(GolandWing, MotionBelowFlutterDecays) {
  // From 0.5 s on, after the gust and the faster-decaying modes: the tip twist follows the bending-torsion mode.
  const FreeMotion run = FreeRun("flutter_below.yaml", 0.5);
  std::printf("130 m/s: rate %.4f 1/s, eigen %.4f 1/s; books %.3g J of %.3g J\n", run.rate, run.eigen_rate, run.books,
              run.throughput);
  ASSERT_LT(run.eigen_rate, 0.0);
  EXPECT_LT(run.rate, 0.0);
  EXPECT_LT(run.books, kBooks * run.throughput);
}

TEST(GolandWing, MotionAboveFlutterGrows) {
  // The same 3.5% above flutter: the twist grows (measured 1.62 1/s against the root's 1.80 1/s, see
  // docs/validation.md: not yet explained, so only the sign is checked).
  const FreeMotion run = FreeRun("flutter_above.yaml", 0.5);
  std::printf("142 m/s: rate %.4f 1/s, eigen %.4f 1/s; books %.3g J of %.3g J\n", run.rate, run.eigen_rate, run.books,
              run.throughput);
  ASSERT_GT(run.eigen_rate, 0.0);
  EXPECT_GT(run.rate, 0.0);
  EXPECT_LT(run.books, kBooks * run.throughput);
}

}  // namespace goland_wing_test
}  // namespace flexmbd
