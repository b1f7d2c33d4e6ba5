// The static equilibrium a user expects of a pendulum near its stops, run the user's way (flexmbd_run on YAML,
// default settings): the nearest one reachable from the start without passing a stop, resting on the stop where the
// load presses it there, hanging otherwise (docs/theory.md, "Static increments"). A rigid pendulum 0.01 rad off its
// rigid stop, gravity pressing it on, was reported "open, gap 9.89602 m", hanging 15.75 turns away: near the
// horizontal the joint has almost no stiffness and Newton's first increment turned it by 100 rad.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "runner_equilibrium.hpp"
#include "runner_output.hpp"
#include "yaml_text.hpp"

namespace flexmbd {
namespace static_stop_reach_test {

constexpr double kG = 9.81, kPi = 3.14159265358979323846;
// pend_h.urdf: 1 kg at 1 m from a pivot about y, horizontal at 0; gravity -z turns it to +q (droop), +z to -q.
// Its stops have radius 0.1 m.
constexpr double kRadius = 0.1;
// Equilibria solved to the Newton tolerance (solver.tol 1e-6 relative on forces, default): an angle where the
// gravity stiffness m g L is the only one (hanging) to 1e-6 rad; a rigid stop's gap to the constraint tolerance
// (1e-11 m) and its force to 1e-6 relative.
constexpr double kHanging = 1.0e-6, kOnStop = 1.0e-10, kForce = 1.0e-6;

std::string Yaml(double start, const std::string& stops, double gravity_z) {
  return "joints: {pivot: {initial: {position: " + std::to_string(start) + "}, backlash: {" + stops +
         "}}}\nsolver: {analysis: static, gravity: [0, 0, " + std::to_string(gravity_z) + "]}";
}

std::vector<double> Equilibrium(const std::string& name, const std::string& yaml, test::CsvTable* csv) {
  return test::EquilibriumRow("test/data/urdf/pend_h.urdf", yaml, name, csv);
}

TEST(StaticStopReach, PendulumPressedTowardsItsRigidStopRestsOnIt) {
  // 0.01 rad above the horizontal, its upper stop at 0 below it: on the stop at 0 with m g L / rho = 98.1 N.
  test::CsvTable csv;
  const std::vector<double> row = Equilibrium("rigid_towards", Yaml(-0.01, "upper: 0.0, radius_upper: 0.1", -kG), &csv);
  ASSERT_FALSE(row.empty());
  EXPECT_NEAR(row[csv.Column("joint.pivot.position")], 0.0, kOnStop);
  EXPECT_EQ(row[csv.Column("stop.pivot.upper.in_contact")], 1.0);
  EXPECT_NEAR(row[csv.Column("stop.pivot.upper.force")], kG / kRadius, kForce * kG / kRadius);
}

TEST(StaticStopReach, PendulumPressedTowardsItsElasticStopRestsOnItsApproach) {
  // The same onto a linear stop of 1e6 N/m: rho k rho q = m g L cos q, q = 9.80999528e-4 rad (hand Newton).
  double q = 0;
  for (int k = 0; k < 50; ++k) {
    q -= (1.0e4 * q - kG * std::cos(q)) / (1.0e4 + kG * std::sin(q));
  }
  test::CsvTable csv;
  const std::vector<double> row = Equilibrium(
      "elastic_towards",
      Yaml(-0.01, "upper: 0.0, radius_upper: 0.1, stop: {type: elastic, law: linear, stiffness: 1.0e6}", -kG), &csv);
  ASSERT_FALSE(row.empty());
  EXPECT_NEAR(row[csv.Column("joint.pivot.position")], q, kForce * q);
  EXPECT_NEAR(row[csv.Column("stop.pivot.upper.force")], kG * std::cos(q) / kRadius, kForce * kG / kRadius);
}

TEST(StaticStopReach, PendulumLoadedAwayFromItsStopHangsWithinHalfATurn) {
  // Gravity +z turns it away from its upper stop at 0: it hangs at -pi/2, the stop open by rho pi/2, rigid or elastic.
  for (const std::string stop : {"stop: {type: rigid}", "stop: {type: elastic, law: hertz, stiffness: 1.0e6}"}) {
    test::CsvTable csv;
    const std::vector<double> row =
        Equilibrium("away", Yaml(-0.01, "upper: 0.0, radius_upper: 0.1, " + stop, kG), &csv);
    ASSERT_FALSE(row.empty()) << stop;
    EXPECT_NEAR(row[csv.Column("joint.pivot.position")], -kPi / 2, kHanging) << stop;
    EXPECT_EQ(row[csv.Column("stop.pivot.upper.in_contact")], 0.0) << stop;
  }
}

TEST(StaticStopReach, PendulumJustPastTheHorizontalHangsBelowWithoutPassingItsStop) {
  // Started 0.01 rad below and above the horizontal, a lower stop at -0.5 rad above it: it hangs at +pi/2. From
  // above, where its stiffness is negative, Newton's increment headed for standing upright through the stop.
  for (const double start : {0.01, -0.01}) {
    test::CsvTable csv;
    const std::vector<double> row =
        Equilibrium("past_horizontal", Yaml(start, "lower: -0.5, radius_lower: 0.1", -kG), &csv);
    ASSERT_FALSE(row.empty()) << start;
    EXPECT_NEAR(row[csv.Column("joint.pivot.position")], kPi / 2, kHanging) << start;
    EXPECT_EQ(row[csv.Column("stop.pivot.lower.in_contact")], 0.0) << start;
  }
}

// Exactly horizontal, gravity's stiffness m g L sin q is zero and the hinge has none: the iteration matrix was singular
// ("singular iteration matrix after 1 Newton iteration(s)" in load increment 1) unless a rigid stop could be closed.
// Its upper stop 0.3 rad below, the pendulum rests on it: the contact carries the weight's moment, rho F = m g L cos q.
// The balance solved by hand with Newton for the stop's law F(a), a = rho (q - 0.3) its approach [m].
double RestingAngle(double stiffness, double exponent) {
  double q = 0.3 + 0.01;
  for (int k = 0; k < 100; ++k) {
    const double a = kRadius * (q - 0.3);
    const double residual = kRadius * stiffness * std::pow(a, exponent) - kG * std::cos(q);
    const double slope = kRadius * kRadius * stiffness * exponent * std::pow(a, exponent - 1) + kG * std::sin(q);
    q -= residual / slope;
  }
  return q;
}

TEST(StaticStopReach, HorizontalPendulumRestsOnTheStopItsWeightPushesItTo) {
  struct Case {
    std::string stop;
    double stiffness, exponent;  // of the elastic law; 0: rigid
  };
  for (const Case& c : {Case{"stop: {type: elastic, law: hertz, stiffness: 1.0e6}", 1.0e6, 1.5},
                        Case{"stop: {type: elastic, law: linear, stiffness: 1.0e6}", 1.0e6, 1.0},
                        Case{"stop: {type: rigid}", 0.0, 0.0}}) {
    const double q = c.stiffness > 0 ? RestingAngle(c.stiffness, c.exponent) : 0.3;
    test::CsvTable csv;
    const std::vector<double> row =
        Equilibrium("horizontal", Yaml(0.0, "lower: -0.3, radius_lower: 0.1, upper: 0.3, radius_upper: 0.1, " + c.stop,
                                       -kG),
                    &csv);
    ASSERT_FALSE(row.empty()) << c.stop;
    // The approach q - 0.3 to the Newton tolerance, 1e-6 relative on forces (a Hertz approach to 2/3 of that); on
    // the rigid stop the gap to the constraint tolerance.
    EXPECT_NEAR(row[csv.Column("joint.pivot.position")], q, c.stiffness > 0 ? kForce * (q - 0.3) : kOnStop) << c.stop;
    EXPECT_EQ(row[csv.Column("stop.pivot.upper.in_contact")], 1.0) << c.stop;
    EXPECT_EQ(row[csv.Column("stop.pivot.lower.in_contact")], 0.0) << c.stop;
    // The resting torque is the weight's moment.
    EXPECT_NEAR(-row[csv.Column("stop.pivot.upper.torque")], kG * std::cos(q), kForce * kG) << c.stop;
  }
}

TEST(StaticStopReach, AnEquilibriumMoreThanATurnAwayIsRefusedWithTheJointNamed) {
  // Without gravity a spring with its rest 7 rad away holds the pendulum there, more than a turn from its start: not
  // the equilibrium nearest to it, refused with exit status 3 (a run that failed) naming the joint and its turn.
  // Started within a turn of it, it is found.
  const std::string wound = "joints: {pivot: {spring: {k: 10.0, rest: 7.0}, initial: {position: START}}}\n"
                            "solver: {analysis: static, gravity: [0, 0, 0]}";
  const std::string far = test::Replaced(wound, "START", "0.0");
  const std::string output = test::RunnerOutput("test/data/urdf/pend_h.urdf", far, "wound_far", 3);
  EXPECT_NE(output.find("the equilibrium Newton found turns joint pivot by 7 rad (1.11408 turns) from its start, "
                        "more than a turn"),
            std::string::npos)
      << output;
  test::CsvTable csv;
  const std::vector<double> row = Equilibrium("wound_near", test::Replaced(wound, "START", "3.0"), &csv);
  ASSERT_FALSE(row.empty());
  EXPECT_NEAR(row[csv.Column("joint.pivot.position")], 7.0, kHanging);
}

}  // namespace static_stop_reach_test
}  // namespace flexmbd
