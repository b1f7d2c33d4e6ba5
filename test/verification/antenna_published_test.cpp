// The published space antenna (config/antenna_published/, docs/validation.md) from its own files, each case cut
// to its first 3 s (the drive's ramp, the first sticking of B2 and B3) and sampled at every step. The full 200 s
// runs and their comparison with the publication are in docs/validation.md.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/math/time_function.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "friction_bound.hpp"
#include "sample_error.hpp"

namespace flexmbd {
namespace antenna_published_test {

constexpr double kShortRun = 3.0;  // [s]
// The drive is a linear constraint on phi_1, met by each Newton update to round-off (observed: 7e-18 rad).
constexpr double kDriveTolerance = 1e-12;  // [rad]
// Nothing acts out of the deployment plane x-z and the sections are symmetric, so the beams never leave it
// (observed: 0 m); a round-off bound.
constexpr double kOutOfPlaneTolerance = 1e-12;  // [m]

// The case as its files give it: 200 s, samples at 20 Hz.
ModelSpec WholeCase(int number) {
  const std::string dir = std::string(FLEXMBD_SOURCE_DIR) + "/config/antenna_published/";
  return LoadModelSpec(dir + "antenna_published.urdf", dir + "case" + std::to_string(number) + ".yaml");
}

ModelSpec Case(int number) {
  ModelSpec spec = WholeCase(number);
  spec.solver.t_end = kShortRun;
  spec.output.rate_hz = 0;  // every accepted step
  return spec;
}

const TimeFunctionSpec& RootDrive(const ModelSpec& spec) {
  const auto root =
      std::find_if(spec.joints.begin(), spec.joints.end(), [](const JointSpec& j) { return j.name == "B1"; });
  return root->effects.at(0).drives.at(0);
}

struct ShortRun {
  OutputSample first, last;
  double drive_error = 0;      // largest |phi_1 - f(t)| [rad]
  double out_of_plane = 0;     // largest |u_y| at the panels' mid-spans [m]
  double friction_bound = 0;   // largest |friction torque| / (mu_s rho N)
  double books = 0;            // E_f + dissipated + numerical - external - E_0 [J]
  double throughput = 0;       // energy through the books [J]
  double tol = 0;              // Newton's relative tolerance
};

ShortRun Run(const ModelSpec& spec) {
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  ShortRun run;
  bool started = false;
  simulation.Run([&](const OutputSample& s) {
    if (!started) run.first = s;
    started = true;
    run.last = s;
    run.drive_error = std::max(run.drive_error, std::abs(s.position[0] - Evaluate(RootDrive(spec), s.t)));
    for (const BeamStationSample& station : s.beam_stations) {
      run.out_of_plane = std::max(run.out_of_plane, std::abs(station.displacement.y()));
    }
    run.friction_bound = std::max(run.friction_bound, test::StaticBoundRatio(spec, model, s));
  });
  const OutputSample& f = run.first;
  const OutputSample& l = run.last;
  run.books = l.total() + l.dissipated + l.numerical_dissipation - l.external_work - f.total();
  run.throughput = f.total() + l.dissipated + l.numerical_dissipation + std::abs(l.external_work);
  run.tol = model.solver().tol;
  return run;
}

void ExpectShortRunHolds(int number) {
  const ModelSpec spec = Case(number);
  ShortRun run;
  ASSERT_NO_THROW(run = Run(spec)) << "case " << number;
  EXPECT_DOUBLE_EQ(run.last.t, kShortRun) << "case " << number;
  EXPECT_LE(run.drive_error, kDriveTolerance) << "case " << number;
  EXPECT_LE(run.out_of_plane, kOutOfPlaneTolerance) << "case " << number;
  // Friction torques within the static bound mu_s rho N on every step, as the other friction cases (observed 0.995).
  EXPECT_LE(run.friction_bound, 1.0 + 1e-9) << "case " << number;
  // The books close to Newton's tolerance times the energy that passed through them (T6), as antenna_case_test
  // (observed: 1.2e-11 J against bounds of 1.4e-7 J).
  EXPECT_NEAR(run.books, 0.0, run.tol * run.throughput) << "case " << number;
  // The drive did work on the antenna: the run is not trivially at rest.
  EXPECT_GT(run.last.external_work, 0.0) << "case " << number;
}

TEST(AntennaPublished, Case0DampersShortRunHoldsItsInvariants) { ExpectShortRunHolds(0); }

TEST(AntennaPublished, Case1FrictionShortRunHoldsItsInvariants) { ExpectShortRunHolds(1); }

TEST(AntennaPublished, Case2DoubledPreloadShortRunHoldsItsInvariants) { ExpectShortRunHolds(2); }

// Published: in case 1 the longest sticking is at the start, at B3; case 2 sticks more. B2 and B3 start at rest,
// hence stuck; the preload (2.5 and 5 N at B2 and B3, doubled in case 2) keeps B3 stuck longer, and longer in
// case 2 (full runs: B3 breaks away at 0.80 s in case 1 and 1.28 s in case 2, B2 at 0.28 and 0.34 s).
double FirstBreakaway(const ModelSpec& spec, const std::string& joint) {
  const Model model = BuildModel(spec);
  const auto it = std::find_if(model.frictions().begin(), model.frictions().end(),
                               [&](const FrictionInfo& f) { return f.joint == joint; });
  const size_t k = static_cast<size_t>(it - model.frictions().begin());
  Simulation simulation(model);
  double breakaway = -1;
  simulation.Run([&](const OutputSample& s) {
    if (breakaway < 0 && !s.friction[k].sticking) breakaway = s.t;
  });
  return breakaway;
}

TEST(AntennaPublished, B3SticksLongestAtTheStartAndLongerWithDoubledPreloads) {
  const double b2_case1 = FirstBreakaway(Case(1), "B2");
  const double b3_case1 = FirstBreakaway(Case(1), "B3");
  const double b3_case2 = FirstBreakaway(Case(2), "B3");
  EXPECT_GT(b2_case1, 0.0);
  EXPECT_GT(b3_case1, b2_case1);
  EXPECT_GT(b3_case2, b3_case1);
}

// Case 0 as its files give it (200 s, samples at 20 Hz), run once for the tests that read it at default settings.
struct WholeRun {
  std::array<double, 4> peak = {0, 0, 0, 0};  ///< largest |phi_1..phi_4| over the samples [rad]
  long attempted = 0;
  long newton_iterations = 0;
};

const WholeRun& Case0AsShipped() {
  static const WholeRun run = [] {
    const Model model = BuildModel(WholeCase(0));
    EXPECT_EQ(model.variable_names().at(0), "B1");
    EXPECT_EQ(model.variable_names().at(3), "B4");
    Simulation simulation(model);
    WholeRun whole;
    simulation.Run([&](const OutputSample& s) {
      for (int k = 0; k < 4; ++k) whole.peak[k] = std::max(whole.peak[k], std::abs(s.position[k]));
    });
    whole.attempted = simulation.statistics().accepted + simulation.statistics().rejected();
    whole.newton_iterations = simulation.statistics().newton_iterations;
    return whole;
  }();
  return run;
}

// The converged peaks of phi_2..phi_4: a run at fixed 1e-3 s steps (200,000 steps; error_tol 1e-6 gives the same to
// 0.002%, docs/validation.md), its 20 Hz samples (bench/reference_cases/against_converged.py antenna_published_0).
constexpr std::array<double, 3> kConvergedPeaks = {0.19015673, 0.13530643, 0.13164385};  // [rad]

// Issue 13: the flexible antenna with dampers, 200 s, in at most 2,000 steps with hinge peaks within 1% of a
// converged run. Measured: 697 steps, peaks within 0.08%.
TEST(AntennaPublished, Case0WholeRunWithin2000StepsAndOnePercentOfConvergedPeaks) {
  const WholeRun& run = Case0AsShipped();
  EXPECT_LE(run.attempted, 2000);
  // Issue 12: beam dissipation terms started only where they dissipated a step before (docs/theory.md, "Newton
  // iteration"). Measured 2,974 iterations over all solves of all 696 attempted steps (3,306 when every beam
  // started its term on); the bound is 5% above, below the old count by 6%.
  EXPECT_LE(run.newton_iterations, 3120);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(run.peak[k + 1], kConvergedPeaks[k], 0.01 * kConvergedPeaks[k]) << "phi_" << k + 2;
  }
}

// Issue 13's aim for the default tolerance, as docs/theory.md ("What the aim means") reads it: each hinge's peak
// within 1e-3 of its converged value, relative. Case 0 stands for the reference cases: a beam model run at the
// default error_tol, its peaks reached in the deployment's first 20 s. Measured 7.5e-4 (phi_3), 5.8e-5 (phi_2) and
// 9.8e-5 (phi_4); at error_tol 3e-4 phi_3 is 2.1e-3 off and at 1e-3 6.0e-3 (bench/README.md, twenty-fourth
// session), so the bound tells the default from a threefold looser one. The converged peaks are known to 2e-5 (the
// fixed 1e-3 s and error_tol 1e-6 runs agree so far).
TEST(AntennaPublished, Case0HingePeaksAtTheDefaultToleranceWithinOneThousandthOfConverged) {
  constexpr double kAim = 1.0e-3;
  const WholeRun& run = Case0AsShipped();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(run.peak[k + 1], kConvergedPeaks[k], kAim * kConvergedPeaks[k]) << "phi_" << k + 2;
  }
}

// Issue 13 on the project's beam case: case 0's error falls with the tolerance and the adaptive run takes fewer
// steps than fixed steps of its accuracy. The error is bench/work_precision's: the largest difference of the four
// hinge angles over the 20 Hz samples from a converged run, relative to the largest angle (B2's, 0.19 rad).
struct HingeRun {
  std::vector<double> angles;  ///< phi_1..phi_4 of each sample, one sample after another [rad]
  long steps = 0;              ///< attempted (accepted and rejected)
};

HingeRun RunHinges(const ModelSpec& spec) {
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  HingeRun run;
  simulation.Run([&](const OutputSample& s) {
    run.angles.insert(run.angles.end(), s.position.data(), s.position.data() + 4);
  });
  run.steps = simulation.statistics().accepted + simulation.statistics().rejected();
  return run;
}

double HingeError(const HingeRun& run, const HingeRun& reference) {
  return test::RelativeSampleError(run.angles, reference.angles);
}

HingeRun Case0WithTolerance(double error_tol) {
  ModelSpec spec = WholeCase(0);
  spec.solver.error_tol = error_tol;
  return RunHinges(spec);
}

HingeRun Case0WithFixedSteps(double steps) {
  ModelSpec spec = WholeCase(0);
  spec.solver.adaptive = false;
  spec.solver.dt = spec.solver.t_end / steps;
  return RunHinges(spec);
}

// The whole 200 s at the YAML's settings (dt_max 1 s): the gain is in the 195 s of slow decay after the deployment.
// Cut to 20 s, the adaptive runs take as many steps as fixed steps of their error (measured at error_tol 1e-4: 315
// steps for 1.0e-3, where fixed steps need 280), so a shorter run would not show the claim. One test for both
// claims, so that the reference is run once. Reference: error_tol 1e-6 (5,020 steps; 1e-7 would take 12,450), 4.6e-5
// from the converged run (fixed 1e-3 s steps, 6.5e-7 from fixed 2e-3 s ones): 12% of the smallest error compared,
// and both margins below hold with it added to or taken from every error.
TEST(AntennaPublished, Case0ErrorFallsWithTheToleranceAndAdaptiveStepsBeatTwiceAsManyFixedSteps) {
  const HingeRun reference = Case0WithTolerance(1.0e-6);
  const HingeRun loose = Case0WithTolerance(1.0e-3);
  const HingeRun fine = Case0WithTolerance(1.0e-5);
  // At least 10x per 100x of tolerance (issue 13); measured 2.0e-2 and 3.3e-4 at 1e-3 and 1e-5 (61x; 53x against
  // the converged run, with linear samples).
  EXPECT_LT(HingeError(fine, reference), HingeError(loose, reference) / 10);
  // At the default error_tol 1e-4 fixed steps reach the adaptive run's error in 2.4 times its attempted steps
  // (bench/README.md, "Work-precision"): twice as many fixed steps are still less accurate (measured: 697 steps
  // for 2.76e-3 against 1,394 fixed steps for 4.02e-3; with linear samples between step ends 2.81e-3 and 4.17e-3,
  // 2.85e-3 and 4.19e-3 against the converged run).
  const HingeRun adaptive = Case0WithTolerance(1.0e-4);
  const HingeRun fixed = Case0WithFixedSteps(2.0 * static_cast<double>(adaptive.steps));
  EXPECT_LT(HingeError(adaptive, reference), HingeError(fixed, reference)) << adaptive.steps << " steps";
}

}  // namespace antenna_published_test
}  // namespace flexmbd
