// Static analysis of joints resting on elastic stops, run the user's way (flexmbd_run on YAML, default settings):
// a joint at first touch of a Hertz stop has no stiffness (V'' = 1.5 k a^0.5 vanishes at a = 0), and its iteration
// matrix was singular; from a small gap it went on from an approach of micrometres and failed. A static iteration
// now takes a least stiffness in contact and updates the approach in the force (docs/theory.md, "Static
// increments"); the eigen-analysis about the equilibrium takes V'' at the approach found.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "runner_equilibrium.hpp"
#include "runner_output.hpp"
#include "yaml_text.hpp"

namespace flexmbd {
namespace static_elastic_stop_test {

constexpr double kG = 9.81, kPi = 3.14159265358979323846;
// pend_h.urdf: 1 kg at 1 m from a pivot about y, horizontal at 0 (+q droops); its moment of inertia about the pivot.
constexpr double kMass = 1.0, kArm = 1.0, kInertia = kMass * kArm * kArm + 1.0e-4;
// Its upper stop at 0, radius 0.1 m, k 1e6 (N/m^1.5 Hertz, N/m linear).
constexpr double kRadius = 0.1, kStiffness = 1.0e6;
// The static residual is solved to solver.tol 1e-6 relative (default): the force to that, the approach to 2/3 of it
// for Hertz. 2e-6 holds both with the round-off of the hand solution.
constexpr double kStatic = 2.0e-6;

struct Balance {
  double angle = 0;      ///< [rad]
  double force = 0;      ///< contact force [N]
  double frequency = 0;  ///< of the pendulum on the stop [Hz]
};

// The hand equilibrium of the pendulum pressed onto the stop by gravity (m g L cos q) and a moment [N m] about the
// pivot: rho k (rho q)^n = m g L cos q + moment, by Newton on the scalar equation; and its frequency about it,
// sqrt((rho^2 n k a^(n-1) + m g L sin q) / I), the stop's tangent stiffness and gravity's.
Balance HandBalance(double exponent, double gravity, double moment) {
  double q = 0.02;
  for (int k = 0; k < 100; ++k) {
    const double a = kRadius * q;
    const double r = kMass * gravity * kArm * std::cos(q) + moment - kRadius * kStiffness * std::pow(a, exponent);
    const double dr = -kMass * gravity * kArm * std::sin(q) -
                      kRadius * kRadius * exponent * kStiffness * std::pow(a, exponent - 1.0);
    q -= r / dr;
  }
  const double a = kRadius * q;
  const double stiffness = kRadius * kRadius * exponent * kStiffness * std::pow(a, exponent - 1.0);
  return {q, kStiffness * std::pow(a, exponent),
          std::sqrt((stiffness + kMass * gravity * kArm * std::sin(q)) / kInertia) / (2.0 * kPi)};
}

std::string PendulumYaml(const std::string& law, double start, const std::string& solver, const std::string& loads) {
  return "joints: {pivot: {initial: {position: " + std::to_string(start) +
         "}, backlash: {upper: 0.0, radius_upper: 0.1, stop: {type: elastic, law: " + law +
         ", stiffness: 1.0e6}}}}\nsolver: " + solver + "\n" + loads;
}

void ExpectOnTheStop(const std::string& name, const std::string& yaml, const Balance& expected) {
  test::CsvTable csv;
  const std::vector<double> row = test::EquilibriumRow("test/data/urdf/pend_h.urdf", yaml, name, &csv);
  ASSERT_FALSE(row.empty()) << name;
  EXPECT_NEAR(row[csv.Column("joint.pivot.position")], expected.angle, kStatic * expected.angle) << name;
  EXPECT_NEAR(row[csv.Column("stop.pivot.upper.force")], expected.force, kStatic * expected.force) << name;
  EXPECT_EQ(row[csv.Column("stop.pivot.upper.in_contact")], 1.0) << name;
}

TEST(StaticElasticStop, PendulumAtZeroGapPressesItsHertzStopToTheBalance) {
  // Horizontal at first touch of its Hertz stop: 98.08 N, approach 2.1267e-3 m (q 0.021267 rad). It was singular.
  ExpectOnTheStop("hertz0", PendulumYaml("hertz", 0.0, "{analysis: static}", ""), HandBalance(1.5, kG, 0.0));
}

TEST(StaticElasticStop, PendulumAtZeroGapPressesItsLinearStopToTheBalance) {
  ExpectOnTheStop("linear0", PendulumYaml("linear", 0.0, "{analysis: static}", ""), HandBalance(1.0, kG, 0.0));
}

TEST(StaticElasticStop, PendulumFromAGapReachesTheSameBalance) {
  // 1e-6 rad off the stop failed; 1e-3 rad off it ended 1000 rad away ("open, gap 100.06 m"); 0.1 rad worked.
  for (const double start : {-1.0e-6, -1.0e-3, -0.1}) {
    ExpectOnTheStop("hertz_gap" + std::to_string(start), PendulumYaml("hertz", start, "{analysis: static}", ""),
                    HandBalance(1.5, kG, 0.0));
  }
}

TEST(StaticElasticStop, StopPressedByAMomentAloneTakesItsApproachInOneBalance) {
  // Without gravity a moment of 9.81 N m presses the stop: nothing else holds the joint, and the approach is the
  // law's inverse of 98.1 N, (98.1 / 1e6)^(2/3) = 2.1271e-3 m. Then gravity and the moment together (196 N).
  ExpectOnTheStop("hertz_moment",
                  PendulumYaml("hertz", 0.0, "{analysis: static, gravity: [0, 0, 0]}",
                               "loads: [{body: bob, moment: [0, 9.81, 0]}]"),
                  HandBalance(1.5, 0.0, 9.81));
  ExpectOnTheStop("hertz_pressed",
                  PendulumYaml("hertz", 0.0, "{analysis: static}", "loads: [{body: bob, moment: [0, 9.81, 0]}]"),
                  HandBalance(1.5, kG, 9.81));
}

TEST(StaticElasticStop, EigenAnalysisOnTheStopTakesItsTangentStiffnessAtTheApproachFound) {
  // static_first eigen-analysis at zero gap: the one mode of the rigid pendulum on its stop at
  // sqrt((rho^2 V''(a) + m g L sin q) / I): Hertz 4.1864 Hz (V'' = 1.5 k a^0.5), linear 15.915 Hz (V'' = k), with
  // and without a moment pressing it. The frequency goes as the square root of a stiffness known to kStatic.
  const std::string eigen = "{analysis: eigen, eigen: {modes: 1, static_first: true}}";
  const std::string moment = "loads: [{body: bob, moment: [0, 9.81, 0]}]";
  struct Case {
    const char* name;
    std::string law, loads;
    Balance expected;
  };
  for (const Case& c : {Case{"eigen_hertz", "hertz", "", HandBalance(1.5, kG, 0.0)},
                        Case{"eigen_linear", "linear", "", HandBalance(1.0, kG, 0.0)},
                        Case{"eigen_hertz_pressed", "hertz", moment, HandBalance(1.5, kG, 9.81)}}) {
    const std::string output =
        test::RunnerOutput("test/data/urdf/pend_h.urdf", PendulumYaml(c.law, 0.0, eigen, c.loads), c.name);
    EXPECT_NEAR(test::TableFrequency(output, 1), c.expected.frequency, kStatic * c.expected.frequency) << c.name;
  }
}

TEST(StaticElasticStop, BladeRestsOnItsHertzDroopStopWithTheMomentOfItsWeight) {
  // hbeam_static_rigid.yaml's blade (1 m, 2 kg/m w, EI 1e3, GA 1e7) hinged at its root, on a Hertz droop stop
  // (radius 0.1 m, k 1e6) at zero gap instead of its rigid one; it failed at every load_steps. The stop carries the
  // weight's moment about the hinge over the radius: at the hinge angle q found, the blade's points lie at
  // s cos q - v(s) sin q from the hinge, v the cantilever's deflection, whose integral is w L^5 / (20 EI) +
  // w L^3 / (3 GA), so the force is w (L^2 cos q / 2 - sin q int v) / rho (98.0737 N; 4.4e-5 less than without the
  // bending). Its approach is the law's, (F / k)^(2/3) = rho q, to the static tolerance. The rest of the beam's
  // geometric nonlinearity is of the order of its rotations squared (3e-3 rad): 1e-5 holds the force (measured
  // 2.4e-6).
  constexpr double kGeometric = 1.0e-5;
  std::string yaml = test::SourceText("test/data/yaml/hbeam_static_rigid.yaml");
  yaml = test::Replaced(yaml, "stop: {type: rigid}", "stop: {type: elastic, law: hertz, stiffness: 1.0e6}");
  yaml = test::Replaced(yaml, "output: {beam_stations: {blade: [0.0, 1.0]}}", "");
  test::CsvTable csv;
  const std::vector<double> row = test::EquilibriumRow("test/data/urdf/hbeam.urdf", yaml, "hbeam_hertz", &csv);
  ASSERT_FALSE(row.empty());
  const double q = row[csv.Column("joint.hinge.position")], force = row[csv.Column("stop.hinge.upper.force")];
  const double w = 2.0 * kG, length = 1.0, ei = 1.0e3, ga = 1.0e7;
  const double deflection_integral = w * std::pow(length, 5) / (20.0 * ei) + w * std::pow(length, 3) / (3.0 * ga);
  const double moment_balance = w * (length * length * std::cos(q) / 2.0 - std::sin(q) * deflection_integral) / kRadius;
  EXPECT_NEAR(force, moment_balance, kGeometric * moment_balance);
  EXPECT_NEAR(kRadius * q, std::pow(force / kStiffness, 2.0 / 3.0), kStatic * kRadius * q);
}

}  // namespace static_elastic_stop_test
}  // namespace flexmbd
