// Static analysis of joints resting on rigid stops, run the user's way (flexmbd_run on YAML in test/data/yaml):
// a stop the joint touches holds it with g = 0 (docs/theory.md (C2a)) and the contact force of the closed form,
// unless that force would pull, when the stop opens. The static solver once never closed a rigid stop: a block
// started on its stop had a singular iteration matrix, a blade on its droop stop no converged Newton iteration.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "runner_equilibrium.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace static_rigid_stop_test {

constexpr double kG = 9.81;

std::string DataYaml(const std::string& name) { return test::SourceText("test/data/yaml/" + name); }

TEST(StaticRigidStop, BlockStartedOnItsStopRestsThereWithItsWeightAlongTheIncline) {
  // incline.urdf: 2 kg on a frictionless 30 deg incline, the rigid stop 0.5 m downhill where it starts: it stays at
  // 0.5 m, and the stop carries m g sin 30 = 9.81 N, a balance of two forces exact to round-off.
  constexpr double kRoundOff = 1.0e-12;
  test::CsvTable csv;
  const std::vector<double> row =
      test::EquilibriumRow("test/data/urdf/incline.urdf", DataYaml("incline_stop_static_on.yaml"), "incline_on", &csv);
  ASSERT_FALSE(row.empty());
  EXPECT_NEAR(row[csv.Column("joint.slide.position")], 0.5, kRoundOff);
  EXPECT_EQ(row[csv.Column("stop.slide.upper.in_contact")], 1.0);
  EXPECT_NEAR(row[csv.Column("stop.slide.upper.force")], 2.0 * kG * 0.5, kRoundOff * 10.0);
}

TEST(StaticRigidStop, RunnerSummarySaysNewtonIterationsAndLoadIncrementsNotTimeSteps) {
  // A static analysis has no time steps: "steps: 0 accepted ...; step size 0 to 0 s" was printed for it.
  const std::string output =
      test::RunnerOutput("test/data/urdf/incline.urdf", DataYaml("incline_stop_static_on.yaml"), "incline_on_summary");
  EXPECT_NE(output.find("flexmbd_run: static analysis: "), std::string::npos) << output;
  EXPECT_NE(output.find(" Newton iterations in 10 load increments\n"), std::string::npos) << output;
  EXPECT_EQ(output.find("step size"), std::string::npos) << output;
  // Nor work books: "external work 0 J" stood beside the strain energy the loads put in. The block resting on its
  // stop 0.5 m down a 30 deg incline from its joint 1 m up has the potential m g (1 - 0.5 sin 30) = 14.715 J.
  EXPECT_EQ(output.find("external work"), std::string::npos) << output;
  EXPECT_NE(output.find("flexmbd_run: energy at the equilibrium: potential 14.715 J"), std::string::npos) << output;
}

TEST(StaticRigidStop, RunnerSaysTheStopIsClosedWithItsForceNotContactIntervals) {
  // The block of the test above: a static analysis has no time and no contact intervals (it printed "0 contact
  // interval(s)" for the stop that holds the block); the stop is closed with m g sin 30 = 9.81 N.
  const std::string output =
      test::RunnerOutput("test/data/urdf/incline.urdf", DataYaml("incline_stop_static_on.yaml"), "incline_on_report");
  EXPECT_NE(output.find("flexmbd_run: stop slide upper: closed in the static equilibrium, contact force 9.81 N\n"),
            std::string::npos)
      << output;
  EXPECT_EQ(output.find("interval"), std::string::npos) << output;
  // pend_rev.urdf on an upper stop that would pull: it opens, and the pendulum hangs 0.3 rad from it, a gap of
  // 0.1 m x 0.3.
  const std::string open = test::RunnerOutput(
      "test/data/urdf/pend_rev.urdf",
      "joints: {pivot: {initial: {position: 0.3}, backlash: {upper: 0.3, radius_upper: 0.1, stop: {type: rigid}}}}\n"
      "solver: {analysis: static}\n",
      "pend_upper_report");
  EXPECT_NE(open.find("flexmbd_run: stop pivot upper: open in the static equilibrium, gap 0.03 m\n"),
            std::string::npos)
      << open;
}

TEST(StaticRigidStop, HingedBladeRestsOnItsDroopStopAsAClampedCantilever) {
  // hbeam_static_rigid.yaml: a 1 m blade of 2 kg/m hinged at its root on its rigid droop stop (radius 0.1 m): the
  // stop holds the hinge at 0 with the weight's moment m g L^2 / 2 over the radius, 98.1 N, and the tip deflects as
  // a clamped cantilever's, w L^4 / (8 EI) + w L^2 / (2 GA) = 2.45348e-3 m. The beam is geometrically exact: its
  // rotations of 3e-3 rad change both by relative amounts of their square's order, 1e-5 (measured 2.4e-6 in the
  // force, 4e-6 in the deflection); 1e-4 holds them.
  constexpr double kGeometric = 1.0e-4;
  std::string yaml = DataYaml("hbeam_static_rigid.yaml");
  const std::string output = "output: {beam_stations: {blade: [0.0, 1.0]}}";
  ASSERT_NE(yaml.find(output), std::string::npos);
  yaml.replace(yaml.find(output), output.size(), "");
  yaml += "\noutput: {beam_stations: {blade: [0.0, 1.0]}, csv: " + testing::TempDir() + "hbeam_rigid.csv}\n";
  test::RunnerOutput("test/data/urdf/hbeam.urdf", yaml, "hbeam_rigid");
  const test::CsvTable csv = test::ReadCsv(testing::TempDir() + "hbeam_rigid.csv");
  ASSERT_FALSE(csv.rows.empty());
  const std::vector<double>& row = csv.rows.back();
  const double w = 2.0 * kG, length = 1.0, ei = 1.0e3, ga = 1.0e7, radius = 0.1;
  const double force = w * length * length / 2.0 / radius;
  const double tip = w * std::pow(length, 4) / (8.0 * ei) + w * length * length / (2.0 * ga);
  EXPECT_EQ(row[csv.Column("joint.hinge.position")], 0.0);
  EXPECT_NEAR(row[csv.Column("stop.hinge.upper.force")], force, kGeometric * force);
  EXPECT_NEAR(-row[csv.Column("beam.blade.s1.uz")], tip, kGeometric * tip);
}

// The static equilibrium of pend_rev.urdf started at 0.3 rad on a rigid stop on `side` (radius 0.1 m).
std::vector<double> PendulumOnStop(const std::string& side, test::CsvTable* csv) {
  const std::string yaml = "joints: {pivot: {initial: {position: 0.3}, backlash: {" + side + ": 0.3, radius_" + side +
                           ": 0.1, stop: {type: rigid}}}}\nsolver: {analysis: static}";
  return test::EquilibriumRow("test/data/urdf/pend_rev.urdf", yaml, "pend_" + side, csv);
}

TEST(StaticRigidStop, StopThatWouldPullOpensAndOneThatPushesHolds) {
  // pend_rev.urdf hangs 1 kg 1 m below its pivot; started at 0.3 rad on a stop. A lower stop there holds it against
  // gravity's m g l sin(0.3) over its radius 0.1 m; an upper one would pull it, opens, and the pendulum hangs at 0.
  // Both to the static solve's round-off.
  constexpr double kRoundOff = 1.0e-9;
  test::CsvTable csv;
  std::vector<double> row = PendulumOnStop("lower", &csv);
  ASSERT_FALSE(row.empty());
  EXPECT_NEAR(row[csv.Column("joint.pivot.position")], 0.3, kRoundOff);
  const double holding = kG * std::sin(0.3) / 0.1;
  EXPECT_NEAR(row[csv.Column("stop.pivot.lower.force")], holding, kRoundOff * holding);
  row = PendulumOnStop("upper", &csv);
  ASSERT_FALSE(row.empty());
  EXPECT_NEAR(row[csv.Column("joint.pivot.position")], 0.0, kRoundOff);
  EXPECT_EQ(row[csv.Column("stop.pivot.upper.in_contact")], 0.0);
}

// stick_slip.urdf: 1 kg on a slide along x with no spring, pushed along it by a 5 N load, with rigid stops given by
// `backlash` (flow style), started at `start`; the static analysis or the run of `solver`.
std::string PushedSlider(const std::string& start, const std::string& backlash, const std::string& solver) {
  return "joints: {slider: {initial: {position: " + start + "}, backlash: " + backlash + "}}\n"
         "loads:\n  - {body: mass, force: [5.0, 0.0, 0.0]}\nsolver: " + solver + "\n";
}

TEST(StaticRigidStop, FreeSliderPushedOntoItsStopRestsOnItWithThePushAsTheContactForce) {
  // Nothing but the stop holds the slide: the iteration matrix was singular at the first iteration when the stop was
  // open at the start. The stop the load pushes the slider towards closes, and the slider rests on it with the
  // contact force 5 N: a balance of two forces, exact to round-off, from a gap of 0.3 m and from the stop (gap 0),
  // and on the stop the push faces when the slider has one on either side.
  constexpr double kRoundOff = 1.0e-12;
  struct Case {
    const char *name, *start, *backlash, *stop;
    double position;
  };
  for (const Case& c :
       {Case{"open", "0.2", "{upper: 0.5}", "upper", 0.5}, Case{"closed", "0.5", "{upper: 0.5}", "upper", 0.5},
        Case{"between", "0.2", "{lower: -0.5, upper: 0.5}", "upper", 0.5}}) {
    SCOPED_TRACE(c.name);
    test::CsvTable csv;
    const std::vector<double> row = test::EquilibriumRow(
        "test/data/urdf/stick_slip.urdf", PushedSlider(c.start, c.backlash, "{analysis: static}"),
        std::string("slider_") + c.name, &csv);
    ASSERT_FALSE(row.empty());
    const std::string stop = std::string("stop.slider.") + c.stop;
    EXPECT_NEAR(row[csv.Column("joint.slider.position")], c.position, kRoundOff);
    EXPECT_EQ(row[csv.Column(stop + ".in_contact")], 1.0);
    EXPECT_NEAR(row[csv.Column(stop + ".force")], 5.0, kRoundOff * 5.0);
  }
}

TEST(StaticRigidStop, RunStartedFromTheStaticEquilibriumOfAPushedSliderStaysOnItsStop) {
  // solver.static_first from a gap of 0.3 m: the run starts on the stop, in contact from t = 0, and stays there at
  // rest with the contact force 5 N (to round-off: nothing moves).
  constexpr double kRoundOff = 1.0e-12;
  test::CsvTable csv;
  const std::vector<double> last = test::EquilibriumRow(
      "test/data/urdf/stick_slip.urdf", PushedSlider("0.2", "{upper: 0.5}", "{static_first: true, t_end: 0.1}"),
      "slider_static_first", &csv);
  ASSERT_FALSE(last.empty());
  for (const std::vector<double>& row : {csv.rows.front(), last}) {
    EXPECT_NEAR(row[csv.Column("joint.slider.position")], 0.5, kRoundOff);
    EXPECT_EQ(row[csv.Column("stop.slider.upper.in_contact")], 1.0);
    EXPECT_NEAR(row[csv.Column("stop.slider.upper.force")], 5.0, kRoundOff * 5.0);
  }
}

TEST(StaticRigidStop, FreeSliderPushedAwayFromItsOnlyStopHasNoEquilibriumAndSaysWhy) {
  // Pushed away from its only stop the slider has nothing to rest on: the run fails (exit 3) and says what to check.
  const std::string output = test::RunnerOutput(
      "test/data/urdf/stick_slip.urdf", PushedSlider("0.2", "{lower: -0.5}", "{analysis: static}"), "slider_away", 3);
  EXPECT_NE(output.find("singular iteration matrix"), std::string::npos) << output;
  EXPECT_NE(output.find("a joint free to move with nothing to stop it"), std::string::npos) << output;
}

}  // namespace static_rigid_stop_test
}  // namespace flexmbd
