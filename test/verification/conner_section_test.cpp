// The three-degree-of-freedom typical section of Conner, Tang, Dowell and Virgin (J. Fluids Struct. 11, 1997)
// from its own files (config/conner_section/): structural frequencies, linear flutter speed, and the free motion
// just below and above flutter against the eigen-analysis (docs/validation.md).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace {

const std::string kDir = std::string(FLEXMBD_SOURCE_DIR) + "/config/conner_section/";

ModelSpec Case(const std::string& yaml) { return LoadModelSpec(kDir + "conner_section.urdf", kDir + yaml); }

// Largest real part of the roots at speed U with N inflow states [1/s] (> 0: unstable).
double LeastStableRoot(double U, int states) {
  ModelSpec spec = Case("flutter_eigen.yaml");
  spec.aero_sections.at(0).velocity = U;
  spec.aero_sections.at(0).inflow_states = states;
  const Model model = BuildModel(spec);
  const EigenResult result = EigenAnalysis(model, model.initial_state(), EigenOptions{});
  double worst = -1e300;
  for (const Mode& mode : result.modes) worst = std::max(worst, mode.eigenvalue.real());
  return worst;
}

// The flutter speed by bisection on the sign of the least stable root, to 0.01% (the issue asks 0.1%).
double FlutterSpeed(int states) {
  double stable = 10.0, unstable = 40.0;
  EXPECT_LT(LeastStableRoot(stable, states), 0.0);
  EXPECT_GT(LeastStableRoot(unstable, states), 0.0);
  while (unstable - stable > 1.0e-4 * unstable) {
    const double mid = 0.5 * (stable + unstable);
    (LeastStableRoot(mid, states) > 0 ? unstable : stable) = mid;
  }
  return 0.5 * (stable + unstable);
}

TEST(ConnerSection, StructuralFrequenciesMatchPublished) {
  // flexmbd_run on the case's own files.
  std::ifstream file(kDir + "structure_modes.yaml");
  const std::string yaml((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::string table = test::RunnerOutput("config/conner_section/conner_section.urdf", yaml, "conner_modes");
  // Published 4.443, 9.221 and 19.433 Hz, given to four figures and measured on the rig: 0.2% covers both
  // the rounding of the paper's data and of its frequencies.
  constexpr double kPublished[3] = {4.443, 9.221, 19.433};
  constexpr double kRelative = 2.0e-3;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(test::TableFrequency(table, k + 1), kPublished[k], kRelative * kPublished[k]) << table;
  }
  EXPECT_TRUE(std::isnan(test::TableFrequency(table, 4))) << table;
}

TEST(ConnerSection, FlutterSpeedMatchesConnersTheory) {
  // Conner's theory gives about 23.9 m/s (the rig 24.3): with four or more inflow states the finite-state model
  // is within 2% of it (its C(k) within 1% at the flutter reduced frequency k = w b / U ~ 0.2, plus the
  // rounding of the section's data).
  constexpr double kTheory = 23.9, kRelative = 0.02;
  for (int states : {4, 6, 8}) {
    const double speed = FlutterSpeed(states);
    std::printf("N = %d: flutter at %.3f m/s\n", states, speed);
    EXPECT_NEAR(speed, kTheory, kRelative * kTheory) << states << " states";
  }
  // Quasi-steady (no wake lag) flutters much earlier: the lag of the circulatory lift stabilises this section.
  const double quasi_steady = FlutterSpeed(0);
  std::printf("quasi-steady: flutter at %.3f m/s\n", quasi_steady);
  EXPECT_LT(quasi_steady, (1 - kRelative) * kTheory);
}

// Decay (or growth) rate of the pitch motion over [t0, t1] from its successive peaks: the slope of log|peak|
// against time by least squares [1/s].
double PeakRate(const std::vector<double>& t, const std::vector<double>& x, double t0, double t1) {
  std::vector<double> pt, px;
  for (size_t k = 1; k + 1 < x.size(); ++k) {
    if (t[k] < t0 || t[k] > t1) continue;
    if (std::abs(x[k]) > std::abs(x[k - 1]) && std::abs(x[k]) >= std::abs(x[k + 1])) {
      pt.push_back(t[k]);
      px.push_back(std::log(std::abs(x[k])));
    }
  }
  const double n = pt.size();
  double st = 0, sx = 0, stt = 0, stx = 0;
  for (size_t k = 0; k < pt.size(); ++k) {
    st += pt[k];
    sx += px[k];
    stt += pt[k] * pt[k];
    stx += pt[k] * px[k];
  }
  return (n * stx - st * sx) / (n * stt - st * st);
}

struct FreeMotion {
  double rate = 0;           // of the pitch peaks [1/s]
  double eigen_rate = 0;     // real part of the least stable root at the same speed [1/s]
  double books = 0;          // largest |E - E0 + numerical - external| [J]
  double throughput = 0;     // largest |external work| [J]
};

FreeMotion FreeRun(const std::string& yaml, double t0, double t1) {
  const ModelSpec spec = Case(yaml);
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  const int pitch = model.FindVariable("pitch");
  std::vector<double> t, x;
  FreeMotion run;
  double e0 = NAN;
  simulation.Run([&](const OutputSample& s) {
    t.push_back(s.t);
    x.push_back(s.position[pitch]);
    if (std::isnan(e0)) e0 = s.total();
    run.books = std::max(run.books, std::abs(s.total() - e0 + s.numerical_dissipation + s.dissipated - s.external_work));
    run.throughput = std::max(run.throughput, std::abs(s.external_work));
  });
  run.rate = PeakRate(t, x, t0, t1);
  run.eigen_rate = LeastStableRoot(spec.aero_sections.at(0).velocity, spec.aero_sections.at(0).inflow_states);
  return run;
}

TEST(ConnerSection, FreeDecayBelowFlutterMatchesEigenDamping) {
  // From 1 s on the other modes have decayed (their rates are several times faster): the peaks follow the least
  // damped mode. The peaks of a sampled sine are off by up to (w dt)^2 / 8 relative, which shifts the fitted rate
  // by far less than 2%; default error_tol 1e-4 per step. Fitted up to 2.5 s: later the pitch is below 1e-4 rad,
  // the steps grow against the error test's absolute floor (1e-7 rad) and the 200 Hz samples, interpolated within
  // them, flatten the peaks (the fit over [1, 4] s gave 1.49/s).
  const FreeMotion run = FreeRun("flutter_below.yaml", 1.0, 2.5);
  std::printf("22 m/s: decay %.4f 1/s, eigen %.4f 1/s; books %.3g J of %.3g J\n", -run.rate, -run.eigen_rate, run.books,
              run.throughput);
  ASSERT_LT(run.eigen_rate, 0.0);
  constexpr double kRelative = 0.02;
  EXPECT_NEAR(run.rate, run.eigen_rate, kRelative * std::abs(run.eigen_rate));
  // Energy books: kinetic + potential + numerical dissipation - air's work stays at its start value; the
  // local error of the steps (1e-4 relative per step) bounds what is left, against the energy that flowed.
  constexpr double kBooks = 1.0e-2;
  EXPECT_LT(run.books, kBooks * run.throughput);
}

TEST(ConnerSection, MotionAboveFlutterGrows) {
  // 1.2 s: the motion grows from 1 deg to about 10 deg, where the linear roots still hold; fitted from 0.4 s, when
  // the other modes have decayed.
  const FreeMotion run = FreeRun("flutter_above.yaml", 0.4, 1.2);
  std::printf("26 m/s: growth %.4f 1/s, eigen %.4f 1/s\n", run.rate, run.eigen_rate);
  ASSERT_GT(run.eigen_rate, 0.0);
  constexpr double kRelative = 0.02;
  EXPECT_NEAR(run.rate, run.eigen_rate, kRelative * run.eigen_rate);
}

}  // namespace
}  // namespace flexmbd
