// Coulomb friction sticking inside closed loops (issue 14; docs/theory.md (F7)): a sticking row that repeats the
// other constraint rows, through a drive on the crank or at a crank's dead centre, is left out of its step and
// the constraints it repeats hold the joint. The slider-crank and the four-bar of test/data, with friction on the
// slide or on the rocker's hinge, read from YAML as a user writes it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "flexmbd/io/config_loader.hpp"

#include "closed_forms.hpp"
#include "csv_books.hpp"
#include "friction_bound.hpp"
#include "loop_run.hpp"
#include "runner_output.hpp"
#include "yaml_text.hpp"

namespace flexmbd {
namespace sticking_loop_test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;
constexpr double kCrank = 0.1, kRod = 0.3;  // slider-crank [m], test/data/urdf/slider_crank.urdf
// Newton ends a step with every constraint row below 1e-11 (docs/theory.md, "Newton iteration"): 1e-10 m or rad
// leaves a margin, as in closure_test.cpp.
constexpr double kLoopTolerance = 1.0e-10;
// The books close to Newton's tolerance, 1e-6 of each step's terms accumulated over the steps, partly cancelling:
// the frictionless slider-crank released at dead centre under gravity at these settings closes them to 1.2e-8
// (measured), the runs here to at most 2.5e-8; 1e-7 leaves a margin.
constexpr double kBooksTolerance = 1.0e-7;
// A drive holding a mechanism at rest balances the weights exactly: the drive's force is the static one to
// Newton's force tolerance, 1e-6 of the largest force of the step (default solver.tol); 1e-5 relative leaves a
// margin for the joints' forces that are larger than the drive's.
constexpr double kHoldingTorqueTolerance = 1.0e-5;

const std::string kSliderCrankLoop =
    "closures:\n  wrist_pin: {type: universal, parent: rod, child: slider, xyz: [0.3, 0.0, 0.0], axis: [0, 0, 1], "
    "axis2: [0, 1, 0]}\njoints:\n  crank_pin: {type: spherical}\n";
const std::string kSlideFriction = "  slide: {friction: {mu_s: 0.3, mu_k: 0.2}}\n";

ModelSpec Load(const std::string& urdf, const std::string& yaml_text, const std::string& name) {
  const std::string yaml = testing::TempDir() + name + ".yaml";
  std::ofstream(yaml) << yaml_text;
  return LoadModelSpec(std::string(FLEXMBD_SOURCE_DIR) + "/" + urdf, yaml);
}

// Potential energy of the slider-crank's weights under gravity g_W at crank angle theta [J]: crank (0.5 kg, centre
// at r / 2), rod (0.3 kg, centre midway between the crank pin and the slider) and slider (1 kg) of the URDF.
double SliderCrankPotential(const Vec3& g_W, double theta) {
  const Vec3 pin(kCrank * std::cos(theta), kCrank * std::sin(theta), 0.0);
  const Vec3 slider(kCrank + kRod + test::SliderTravel(kCrank, kRod, theta), 0.0, 0.0);
  return -g_W.dot(0.5 * 0.5 * pin + 0.3 * 0.5 * (pin + slider) + 1.0 * slider);
}

// Potential energy of the four-bar's weights under gravity -y at crank angle theta [J] (test/data/urdf/four_bar.urdf):
// the coupler's far end C where the circles about the crank pin B (0.35 m) and the pivot D (0.25 m) meet, on the
// side the URDF draws (left of B -> D).
double FourBarPotential(double theta) {
  const Eigen::Vector2d B(0.1 * std::cos(theta), 0.1 * std::sin(theta)), D(0.4, 0.0);
  const double d = (D - B).norm(), a = (0.35 * 0.35 - 0.25 * 0.25 + d * d) / (2.0 * d);
  const Eigen::Vector2d along = (D - B) / d, left(-along.y(), along.x());
  const Eigen::Vector2d C = B + a * along + std::sqrt(0.35 * 0.35 - a * a) * left;
  return kG * (0.5 * 0.5 * B.y() + 0.4 * 0.5 * (B.y() + C.y()) + 0.6 * 0.5 * C.y());
}

// dV/dtheta by central differences: truncation e^2 V''' ~ 1e-12, round-off eps V / e ~ 1e-11 [N m].
template <typename Potential>
double HoldingTorque(Potential potential, double theta) {
  constexpr double e = 1.0e-6;
  return (potential(theta + e) - potential(theta - e)) / (2.0 * e);
}

struct FrictionRun {
  test::LoopRun loop;
  double worst_bound_ratio = 0;  // largest |friction force| / (mu_s rho N) over the samples
};

FrictionRun RunWithFriction(const ModelSpec& spec, const Model& model,
                            const std::function<void(const OutputSample&)>& each = {}) {
  FrictionRun run;
  run.loop = test::RunLoop(model, [&](const OutputSample& s, const State&) {
    run.worst_bound_ratio = std::max(run.worst_bound_ratio, test::StaticBoundRatio(spec, model, s));
    if (each) each(s);
  });
  return run;
}

// A loop whose drive turned it and then holds it: the frictional joint slid (it dissipated), and ends stuck with its
// row left out and no friction force; loop, books and the static bound throughout.
void ExpectSlidThenHeld(const FrictionRun& run) {
  const FrictionSample& friction = run.loop.last.friction[0];
  EXPECT_LT(run.loop.worst_constraint, kLoopTolerance);
  EXPECT_LT(std::abs(run.loop.books), kBooksTolerance);
  EXPECT_LE(run.worst_bound_ratio, 1.0);
  EXPECT_GT(friction.work, 0.0);
  EXPECT_TRUE(friction.sticking);
  EXPECT_EQ(friction.torque, 0.0);
}

TEST(StickingLoop, DriveHoldsTheStuckSliderWithTheClosedFormTorque) {
  // The crank driven from 1 to 2 rad in 0.5 s (cosine ramp), then held, with gravity along the slide: the slider
  // slides while the crank turns and sticks once it is held. Its sticking row then repeats the drive through the
  // loop; left out, the drive holds the whole load: its torque is dV/dtheta of the weights, friction none.
  const Vec3 g_W(-kG, 0.0, 0.0);
  const ModelSpec spec = Load(
      "test/data/urdf/slider_crank.urdf",
      kSliderCrankLoop + "  crank_hinge: {drive: {law: cosine_ramp, offset: 1.0, value: 2.0, duration: 0.5}}\n" +
          kSlideFriction + "solver: {t_end: 1.0, gravity: [-9.81, 0.0, 0.0]}\noutput: {rate_hz: 0}\n",
      "sticking_loop_held_slider");
  const Model model = BuildModel(spec);
  const int crank = model.FindVariable("crank_hinge");
  const FrictionRun run = RunWithFriction(spec, model);
  const OutputSample& end = run.loop.last;
  EXPECT_DOUBLE_EQ(end.t, 1.0);
  ExpectSlidThenHeld(run);
  const double holding = HoldingTorque([&](double theta) { return SliderCrankPotential(g_W, theta); }, 2.0);
  EXPECT_NEAR(end.effort[crank], holding, kHoldingTorqueTolerance * std::abs(holding));
}

TEST(StickingLoop, DrivenCrankTurnsTheSliderThroughItsDeadCentres) {
  // One turn at 2 pi rad/s from 1 rad: the slider stops and turns back at crank angles pi and 2 pi, where it
  // comes to rest for an instant; its sticking row there repeats the drive, and it slides on the other way.
  const ModelSpec spec = Load(
      "test/data/urdf/slider_crank.urdf",
      kSliderCrankLoop +
          "  crank_hinge: {drive: {law: linear_ramp, offset: 1.0, value: 7.283185307179586, duration: 1.0}}\n" +
          kSlideFriction + "solver: {t_end: 1.2, gravity: [0.0, -9.81, 0.0]}\noutput: {rate_hz: 0}\n",
      "sticking_loop_turning_slider");
  const Model model = BuildModel(spec);
  const int crank = model.FindVariable("crank_hinge"), slide = model.FindVariable("slide");
  double worst_travel_error = 0;
  const FrictionRun run = RunWithFriction(spec, model, [&](const OutputSample& s) {
    worst_travel_error = std::max(worst_travel_error, std::abs(s.position[slide] -
                                                               test::SliderTravel(kCrank, kRod, s.position[crank])));
  });
  EXPECT_DOUBLE_EQ(run.loop.last.t, 1.2);
  EXPECT_NEAR(run.loop.last.position[crank], 1.0 + 2.0 * kPi, 1e-12);
  EXPECT_LT(worst_travel_error, kLoopTolerance);
  EXPECT_LT(run.loop.worst_constraint, kLoopTolerance);
  EXPECT_LT(std::abs(run.loop.books), kBooksTolerance);
  EXPECT_LE(run.worst_bound_ratio, 1.0);
  EXPECT_GT(run.loop.last.friction[0].work, 0.0);
}

TEST(StickingLoop, SliderStuckAtDeadCentreCannotHoldTheCrank) {
  // Released from rest at dead centre (crank angle 0, all along x) under gravity across the slide. The slider's
  // travel is stationary there (dx/dtheta = 0), so its sticking row repeats the loop's and cannot hold the crank,
  // whatever mu_s: the crank starts with the frictionless angular acceleration alpha = Q / I of the closed form.
  // With the slider fixed to first order the rod turns about the wrist at -1/3 of the crank's rate and its centre
  // moves at r / 2 times it: I = (5e-4 + 0.5 0.05^2) + (0.3 0.05^2 + 2.25e-3 / 9) = 2.75e-3 kg m^2; the weights'
  // generalised force Q = -g (0.5 0.05 + 0.3 0.05) = -0.3924 N m. Checked over the first step (0.01 s at the
  // default settings), in which the row is left out: theta = alpha t^2 / 2 up to the change of I and Q with theta,
  // O(theta^2) = 5e-5 relative at theta = 7e-3 (measured 1.0e-4 for both mu_s, as without friction): 1e-3. A
  // slider that held the crank there would leave it at 0.
  constexpr double kStartTolerance = 1.0e-3;
  const double alpha = -kG * (0.5 * 0.05 + 0.3 * 0.05) / 2.75e-3;
  for (const std::string mu : {"0.3", "10.0"}) {
    const ModelSpec spec = Load(
        "test/data/urdf/slider_crank.urdf",
        kSliderCrankLoop + "  slide: {friction: {mu_s: " + mu + ", mu_k: " + std::to_string(std::stod(mu) * 2 / 3) +
            "}}\nsolver: {t_end: 0.3, gravity: [0.0, -9.81, 0.0]}\noutput: {rate_hz: 0}\n",
        "sticking_loop_dead_centre");
    const Model model = BuildModel(spec);
    const int crank = model.FindVariable("crank_hinge");
    OutputSample first_step;
    const FrictionRun run = RunWithFriction(spec, model, [&](const OutputSample& s) {
      if (first_step.t == 0.0) first_step = s;
    });
    ASSERT_GT(first_step.t, 0.0) << mu;
    EXPECT_NEAR(first_step.position[crank] / (0.5 * alpha * first_step.t * first_step.t), 1.0, kStartTolerance) << mu;
    EXPECT_DOUBLE_EQ(run.loop.last.t, 0.3) << mu;
    EXPECT_LT(run.loop.worst_constraint, kLoopTolerance) << mu;
    EXPECT_LT(std::abs(run.loop.books), kBooksTolerance) << mu;
    EXPECT_LE(run.worst_bound_ratio, 1.0) << mu;
    EXPECT_GT(run.loop.last.friction[0].work, 0.0) << mu;  // the slider slid
  }
}

TEST(StickingLoop, SliderAtDeadCentreUnderAnAxialLoadStaysThere) {
  // Gravity along the slide, away from the crank, at dead centre: the rod carries the slider's weight in tension
  // and the crank's weight has no arm about its hinge, so the mechanism rests; the slider's sticking row repeats
  // the loop's and is left out, and friction takes nothing of the load (it applies no force).
  const ModelSpec spec = Load("test/data/urdf/slider_crank.urdf",
                              kSliderCrankLoop + kSlideFriction +
                                  "solver: {t_end: 0.5, gravity: [9.81, 0.0, 0.0]}\noutput: {rate_hz: 0}\n",
                              "sticking_loop_dead_centre_axial");
  const Model model = BuildModel(spec);
  const FrictionRun run = RunWithFriction(spec, model);
  EXPECT_DOUBLE_EQ(run.loop.last.t, 0.5);
  EXPECT_LT(std::abs(run.loop.last.position[model.FindVariable("crank_hinge")]), kLoopTolerance);
  EXPECT_LT(std::abs(run.loop.last.position[model.FindVariable("slide")]), kLoopTolerance);
  EXPECT_TRUE(run.loop.last.friction[0].sticking);
  EXPECT_EQ(run.loop.last.friction[0].torque, 0.0);
  EXPECT_LT(run.loop.worst_constraint, kLoopTolerance);
}

TEST(StickingLoop, DriveHoldsTheStuckRockerOfAFourBar) {
  // test/data/yaml/four_bar.yaml: the crank driven 0.8 rad, then held, the rocker's hinge with friction: a
  // different loop, with the sticking row on a hinge. Held, the drive's torque is dV/dtheta of the weights.
  const std::string yaml = test::ReadFile(std::string(FLEXMBD_SOURCE_DIR) + "/test/data/yaml/four_bar.yaml");
  const ModelSpec spec = Load("test/data/urdf/four_bar.urdf", yaml, "sticking_loop_four_bar");
  const Model model = BuildModel(spec);
  const FrictionRun run = RunWithFriction(spec, model);
  const OutputSample& end = run.loop.last;
  EXPECT_DOUBLE_EQ(end.t, 1.0);
  ExpectSlidThenHeld(run);
  const double holding = HoldingTorque(FourBarPotential, 0.8);
  EXPECT_NEAR(end.effort[model.FindVariable("crank_hinge")], holding, kHoldingTorqueTolerance * std::abs(holding));
}

TEST(StickingLoop, RunnerRunsTheStuckLoopsThatWereSingular) {
  // The inputs that failed with "singular iteration matrix": the slider-crank released at dead centre, and the
  // four-bar whose rocker sticks while the drive holds the crank at rest at t = 0.
  const std::string dead_centre = test::RunnerOutput(
      "test/data/urdf/slider_crank.urdf",
      kSliderCrankLoop + kSlideFriction + "solver: {t_end: 0.2, gravity: [0.0, -9.81, 0.0]}\noutput: {rate_hz: 0}\n",
      "sticking_loop_runner_dead_centre");
  EXPECT_NE(dead_centre.find("finished at t = 0.2 s"), std::string::npos) << dead_centre;
  const std::string yaml = test::ReadFile(std::string(FLEXMBD_SOURCE_DIR) + "/test/data/yaml/four_bar.yaml");
  const std::string four_bar =
      test::RunnerOutput("test/data/urdf/four_bar.urdf", yaml, "sticking_loop_runner_four_bar");
  EXPECT_NE(four_bar.find("finished at t = 1 s"), std::string::npos) << four_bar;
}

TEST(StickingLoop, FreeFourBarWhoseCrankStrikesItsStopWhileTheRockerSlidesRunsOn) {
  // test/data/yaml/four_bar_crank_stop_friction.yaml through the runner: the rigid impact on the crank's stop reverses
  // the whole loop, the rocker's slip with it, within any step; the friction's landing on that reversal (F2) cut the
  // impact's step below dt_min at 0.147992 s. The run now goes on to its end through five impacts; the first begins
  // where a run at error_tol 1e-6 has it (0.147989 s; at the default 0.147988 s: the landing of (C5') puts it within
  // a small share of a step, 1e-4 s leaves a margin); friction's work never falls; the books close to Newton's
  // tolerance (1e-6 of the throughput, as FrictionWork; measured 2e-9).
  const std::string csv = testing::TempDir() + "four_bar_crank_stop.csv";
  std::string yaml =
      test::ReadFile(std::string(FLEXMBD_SOURCE_DIR) + "/test/data/yaml/four_bar_crank_stop_friction.yaml");
  yaml.replace(yaml.find("output: {rate_hz: 0}"), 20, "output: {rate_hz: 0, csv: " + csv + "}");
  const std::string output = test::RunnerOutput("test/data/urdf/four_bar.urdf", yaml, "four_bar_crank_stop");
  SCOPED_TRACE(output);
  EXPECT_NE(output.find("finished at t = 1 s"), std::string::npos);
  const test::CsvTable table = test::ReadCsv(csv);
  ASSERT_GT(table.rows.size(), 2u);
  double first_contact = -1;
  for (const std::vector<double>& row : table.rows) {
    if (first_contact < 0 && row.at(table.Column("stop.crank_hinge.lower.in_contact")) == 1.0) first_contact = row[0];
  }
  EXPECT_NEAR(first_contact, 0.147989, 1e-4);
  EXPECT_EQ(test::LargestFall(table, "friction.rocker_hinge.work"), 0.0);
  EXPECT_GT(table.rows.back().at(table.Column("friction.rocker_hinge.work")), 0.0);
  const test::CsvBooks books = test::BooksAt(table, table.rows.back());
  EXPECT_LT(std::abs(books.imbalance), 1e-6 * books.throughput);
}

}  // namespace sticking_loop_test
}  // namespace flexmbd
