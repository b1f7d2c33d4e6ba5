// The contact intervals a dynamic run reports (the runner's "stop ...: N contact interval(s)" line) when a contact
// holds at its start: a static analysis (solver.static_first) closed it, so the model's initial state has the stop
// open. The count once started from those initial modes and printed "0 contact interval(s)" for a blade resting on
// its stop in every sample; the contact is one interval from t0, for a rigid stop and an elastic one alike.

#include <gtest/gtest.h>

#include <string>

#include "runner_equilibrium.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace contact_at_start_test {

// hbeam.urdf's blade, 1 m of 2 kg/m in four elements, and the start of its hinge's entry.
constexpr const char* kBladeOnAHinge =
    "beams:\n"
    "  blade: {length: 1.0, elements: 4, damping: 1.0e-4, section: {EA: 1.0e8, GA2: 1.0e7, GA3: 1.0e7, GJ: 1.0e3,"
    " EI2: 1.0e3, EI3: 1.0e3, m: 2.0, m_ii: [1.0e-3, 1.0e-5, 1.0e-5]}}\n"
    "joints:\n"
    "  hinge:\n";

TEST(ContactAtStart, BladeRestingOnItsStopAfterAStaticAnalysisHasOneIntervalFromTheStart) {
  // hbeam.urdf: a flexible blade hinged at its root, resting under gravity on a rigid upper stop at 0 (radius
  // 0.1 m), at rest throughout: the stop force 98.1 N never lets go.
  const std::string yaml = std::string(kBladeOnAHinge) +
      "    backlash: {upper: 0.0, radius_upper: 0.1}\n"
      "solver: {t_end: 0.5, static_first: true}\n";
  const std::string out = test::RunnerOutput("test/data/urdf/hbeam.urdf", yaml, "contact_at_start");
  EXPECT_NE(out.find("stop hinge upper: 1 contact interval(s) [0, 0.5] s"), std::string::npos) << out;
}

TEST(ContactAtStart, BladeRestingOnAnElasticStopAfterAStaticAnalysisHasOneIntervalFromTheStart) {
  // The blade above on a Hertz stop (k 1e6 N/m^1.5), started 0.01 rad off it: the equilibrium presses it with 98.1 N
  // (an approach of 2.1e-3 m), which never lets go. Its interval once opened at the end of the first step ([0.01,
  // 0.5] s), as only a step committed an elastic contact.
  const std::string yaml = std::string(kBladeOnAHinge) +
      "    initial: {position: -0.01}\n"
      "    backlash: {upper: 0.0, radius_upper: 0.1, stop: {type: elastic, law: hertz, stiffness: 1.0e6,"
      " restitution: 0.7}}\n"
      "solver: {t_end: 0.5, static_first: true}\n";
  const std::string out = test::RunnerOutput("test/data/urdf/hbeam.urdf", yaml, "elastic_contact_at_start");
  EXPECT_NE(out.find("stop hinge upper: 1 contact interval(s) [0, 0.5] s"), std::string::npos) << out;
}

// stick_slip.urdf's 1 kg slider pressed by a spring (k 100 N/m, rest 0.1 m) onto a stop at 0.05 m, where it starts at
// rest: a contact that holds at t = 0 without a static analysis, with the force k (rest - stop) = 5 N.
std::string PressedSlider(const std::string& stop) {
  return "joints:\n  slider:\n    spring: {k: 100.0, rest: 0.1}\n    initial: {position: 0.05}\n"
         "    backlash: {upper: 0.05" + stop + "}\n";
}

TEST(ContactAtStart, SliderPressedOntoARigidStopShowsTheContactForceInEveryRowFromTheFirst) {
  // Nothing moves, so every row, the first included, has the slider in contact with the force 5 N (torque -5 N on
  // the slide) to round-off, and the effort (spring plus stop) zero. The first row read the stop open, force 0, while
  // the effort already held the stop's -5 N and the runner reported the contact from t = 0 (explore6).
  constexpr double kRoundOff = 1.0e-12;
  test::CsvTable csv;
  test::EquilibriumRow("test/data/urdf/stick_slip.urdf", PressedSlider("") + "solver: {t_end: 0.1}\n",
                       "pressed_rigid", &csv);
  ASSERT_GT(csv.rows.size(), 2u);
  for (const std::vector<double>& row : csv.rows) {
    EXPECT_EQ(row[csv.Column("stop.slider.upper.in_contact")], 1.0) << "t = " << row[0];
    EXPECT_NEAR(row[csv.Column("stop.slider.upper.force")], 5.0, 5.0 * kRoundOff) << "t = " << row[0];
    EXPECT_NEAR(row[csv.Column("stop.slider.upper.torque")], -5.0, 5.0 * kRoundOff) << "t = " << row[0];
    EXPECT_NEAR(row[csv.Column("joint.slider.effort")], 0.0, 5.0 * kRoundOff) << "t = " << row[0];
  }
}

TEST(ContactAtStart, ElasticStopTouchedAtRestNeverShowsAPullingForce) {
  // The same slider on a linear elastic stop (1e5 N/m, lossless) touching it at t = 0: the approach is 0 there, so the
  // law's force is 0, and a stop never pulls: no row has a negative force. The first row once showed -2.5e-5 N, the
  // extrapolation to a step of length 0 (docs/config.md, "Samples") of forces that grow as h^2 from rest.
  test::CsvTable csv;
  test::EquilibriumRow("test/data/urdf/stick_slip.urdf",
                       PressedSlider(", stop: {type: elastic, law: linear, stiffness: 1.0e5, restitution: 1.0}") +
                           "solver: {t_end: 0.02}\n",
                       "pressed_elastic", &csv);
  ASSERT_GT(csv.rows.size(), 2u);
  EXPECT_EQ(csv.rows.front()[csv.Column("stop.slider.upper.force")], 0.0);
  for (const std::vector<double>& row : csv.rows) {
    EXPECT_GE(row[csv.Column("stop.slider.upper.force")], 0.0) << "t = " << row[0];
  }
}

}  // namespace contact_at_start_test
}  // namespace flexmbd
