// Static analysis against closed-form equilibria.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "case_builders.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "../integration/helpers/csv_table.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace static_test {

TEST(StaticAnalysis, PendulumWithTorsionalSpringBalancesGravity) {
  // Arm upright at phi = 0 (CM at height l above the pivot), torsional spring k, gravity -z: equilibrium
  // k phi = m g l sin(phi). With m g l / k = 2 the nontrivial root is phi* = 1.895494267...
  const double m = 2.0, l = 0.5, g = 9.81, k = m * g * l / 2.0;
  ModelSpec spec = test::Pendulum(m, l, 1.0e-2);
  const Mat3 R_up = AxisAngle(Vec3::UnitY(), -M_PI / 2);  // arm along +z at phi = 0
  spec.joints[0].R_PJ = R_up;
  spec.joints[0].effects[0].springs.push_back({k, 0.0});
  // Start away from the unstable upright equilibrium.
  const double phi0 = 1.0;
  spec.joints[0].initial_position = {phi0};
  spec.bodies[0].R_WB = R_up * AxisAngle(Vec3::UnitY(), phi0);
  spec.solver.analysis = SolverSpec::Analysis::kStatic;
  spec.solver.load_steps = 1;
  spec.solver.tol = 1.0e-12;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  simulation.Run([](const OutputSample&) {});
  const double phi = simulation.state().q[0];
  // Residual of the closed form at the computed angle, relative to the spring torque: Newton to 1e-12.
  constexpr double kBalanceTolerance = 1.0e-9;
  EXPECT_NEAR((k * phi - m * g * l * std::sin(phi)) / (k * phi), 0.0, kBalanceTolerance);
  EXPECT_NEAR(phi, 1.8954942670339809, 1.0e-9);
}

TEST(StaticAnalysis, StaticFirstStartsDynamicsAtRest) {
  // The same pendulum, with static_first and a dynamic run: started from the static equilibrium it must stay
  // there. Reference: the equilibrium angle 1.8954942670339809 of k phi = m g l sin(phi).
  const double m = 2.0, l = 0.5, g = 9.81, k = m * g * l / 2.0;
  ModelSpec spec = test::Pendulum(m, l, 1.0e-2);
  const Mat3 R_up = AxisAngle(Vec3::UnitY(), -M_PI / 2);
  spec.joints[0].R_PJ = R_up;
  spec.joints[0].effects[0].springs.push_back({k, 0.0});
  spec.joints[0].initial_position = {1.0};
  spec.bodies[0].R_WB = R_up * AxisAngle(Vec3::UnitY(), 1.0);
  spec.solver.static_first = true;
  spec.solver.load_steps = 1;
  spec.solver.dt = 1.0e-2;
  spec.solver.t_end = 2.0;
  spec.solver.tol = 1.0e-12;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  double worst_drift = 0;
  simulation.Run([&](const OutputSample& s) {
    worst_drift = std::max(worst_drift, std::abs(s.position[0] - 1.8954942670339809));
  });
  // Equilibrium to Newton accuracy; the dynamics then see residual forces of order 1e-12 relative only.
  constexpr double kDriftTolerance = 1.0e-9;
  EXPECT_LT(worst_drift, kDriftTolerance);
}

// The rod of config/pendulum_stop (2 kg, centre of mass 0.5 m from the hinge, no spring) through the runner with
// `analysis: static` from 0.5 rad: gravity alone holds a mechanism, so its first static tangent has no stiffness
// but the joint's geometric stiffness, which zero multipliers leave out (it was singular: docs/theory.md, static
// analysis). `hinge_yaml` is the hinge's block; the CSV's last row is the equilibrium.
double StaticHingeAngle(const std::string& hinge_yaml, const std::string& name) {
  const std::string out = test::RunnerOutput(
      "config/pendulum_stop/pendulum_stop.urdf",
      "joints: {hinge: {" + hinge_yaml + "}}\nsolver: {analysis: static, gravity: [0.0, 0.0, -9.81]}\n"
      "output: {csv: " + testing::TempDir() + name + ".csv}\n",
      name);
  const test::CsvTable table = test::ReadCsv(testing::TempDir() + name + ".csv");
  EXPECT_FALSE(table.rows.empty()) << out;
  return table.rows.empty() ? std::nan("") : table.rows.back().at(table.Column("joint.hinge.position"));
}

TEST(StaticAnalysis, PendulumWithoutASpringHangsStraightDown) {
  // The rod turns about +y, so its centre of mass (along +x at 0) is straight below the hinge at pi/2; the
  // static solve stops on its increments at tol 1e-6 relative of the motion, quadratically: 1e-9 rad bounds it.
  const double angle = StaticHingeAngle("initial: {position: 0.5}", "static_free_pendulum");
  EXPECT_NEAR(angle, M_PI / 2, 1.0e-9);
}

TEST(StaticAnalysis, PendulumRestsOnItsDroopStopPressedByItsWeight) {
  // Started on its droop stop (the URDF's upper limit, 60 deg below the horizontal; Hertz law k a^1.5, zero
  // stiffness at zero approach), the rod presses the stop at radius r = 0.1 m, approach a = r (q - q_stop), until
  // k a^1.5 r equals the weight's moment m g l cos(q): a = 4.6e-4 m, 4.6e-3 rad past the stop.
  const double m = 2.0, g = 9.81, l = 0.5, k = 5.0e6, r = 0.1, stop = 1.0472;
  const double angle = StaticHingeAngle(
      "initial: {position: 1.0472}, backlash: {radius_lower: 0.1, radius_upper: 0.1, "
      "stop: {type: elastic, law: hertz, stiffness: 5.0e6, exponent: 1.5, restitution: 0.7}}",
      "static_pendulum_on_stop");
  ASSERT_GT(angle, stop) << "the rod should press into its stop";
  // The balance at the angle reached, to the static solve's Newton tolerance (1e-6 relative of the motion).
  const double contact_moment = k * std::pow((angle - stop) * r, 1.5) * r;
  EXPECT_NEAR(contact_moment / (m * g * l * std::cos(angle)), 1.0, 1.0e-6);
}

// A model with nothing to carry is at equilibrium where it starts: each load step's first correction is round-off
// in every unknown, so it converges there (docs/theory.md, "Newton iteration"), one iteration per load step (10 by
// default), and nothing moves beyond the coordinates' round-off. Before, the residual was judged against a zero
// load and the wing with aileron failed in its first load step.
constexpr int kDefaultLoadSteps = 10;

TEST(StaticAnalysis, UnloadedCantileverStaysWhereItIsInOneIterationPerLoadStep) {
  // The Goland wing's beam (config/goland_wing, EA 1e10 N) clamped at its root, no air and no gravity.
  const std::string csv = testing::TempDir() + "static_unloaded_cantilever.csv";
  const std::string out = test::RunnerOutput(
      "config/goland_wing/goland_wing.urdf",
      "beams:\n  wing:\n    length: 6.096\n    elements: 8\n"
      "    section: {EA: 1.0e10, GA2: 1.0e10, GA3: 1.0e10, GJ: 0.987e6, EI2: 9.77e6, EI3: 9.77e8, m: 35.71,"
      " m_ii: [7.446, 0.016, 7.43], offsets: {cg: [0.18288, 0.0]}}\n"
      "solver: {analysis: static, gravity: [0.0, 0.0, 0.0]}\n"
      "output: {csv: " + csv + ", beam_stations: {wing: [6.096]}}\n",
      "static_unloaded_cantilever");
  const test::CsvTable table = test::ReadCsv(csv);
  ASSERT_FALSE(table.rows.empty()) << out;
  const std::vector<double>& equilibrium = table.rows.back();
  EXPECT_EQ(equilibrium.at(table.Column("solver.iterations")), kDefaultLoadSteps);
  // RoundOffFloor of the 6.1 m wing: 100 eps x 6.1 = 1.4e-13 m or rad (measured 0).
  constexpr double kRoundOff = 1.4e-13;
  for (const char* motion : {"ux", "uy", "uz", "rx", "ry", "rz"}) {
    EXPECT_LE(std::abs(equilibrium.at(table.Column(std::string("beam.wing.s0.") + motion))), kRoundOff) << motion;
  }
}

TEST(StaticAnalysis, PendulumHangingAtRestStaysInOneIterationPerLoadStep) {
  // The rod of config/pendulum_stop hanging straight down (pi/2, as above): its weight is carried by the hinge from
  // the first load step's start (the multipliers of the model released at rest), so the hinge stays put.
  char hinge[64];
  std::snprintf(hinge, sizeof(hinge), "initial: {position: %.17g}", M_PI / 2);
  const std::string csv = testing::TempDir() + "static_pendulum_at_rest.csv";
  const std::string out = test::RunnerOutput(
      "config/pendulum_stop/pendulum_stop.urdf",
      std::string("joints: {hinge: {") + hinge + "}}\nsolver: {analysis: static, gravity: [0.0, 0.0, -9.81]}\n"
      "output: {csv: " + csv + "}\n",
      "static_pendulum_at_rest");
  const test::CsvTable table = test::ReadCsv(csv);
  ASSERT_FALSE(table.rows.empty()) << out;
  const std::vector<double>& equilibrium = table.rows.back();
  EXPECT_EQ(equilibrium.at(table.Column("solver.iterations")), kDefaultLoadSteps);
  // The angle to its round-off (100 eps x pi/2 = 3.5e-14 rad).
  EXPECT_NEAR(equilibrium.at(table.Column("joint.hinge.position")), M_PI / 2, 3.5e-14);
}

}  // namespace static_test
}  // namespace flexmbd
