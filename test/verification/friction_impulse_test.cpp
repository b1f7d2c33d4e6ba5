// A stuck frictional joint across an impulse (docs/theory.md (F8)): the two-link arm of test/data, its elbow held by
// a spring against gravity and stuck, its shoulder's drive jumping in rate. The elbow stays stuck, or slides with the
// rate Coulomb's law for impulses gives it, from the closed form of the second arm's impulsive motion; the user's model
// runs through the runner at default settings with the books closed.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "flexmbd/solver/velocity_projection.hpp"

#include "csv_books.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace friction_impulse_test {

// The second arm of two_link_arm.urdf: mass, inertia about its centre of mass (y), elbow to centre of mass; the first
// arm's length (shoulder to elbow).
constexpr double kMass = 1.0, kInertia = 0.083333, kArm = 0.5, kFirstArm = 1.0;
constexpr double kJump = 0.5, kRate = -6.0;  // [s, rad/s]: the shoulder's ramp starts here at this rate

std::string ArmYaml(const std::string& friction) {
  return "joints:\n  B1:\n    drive: {law: linear_ramp, value: " + std::to_string(kRate) +
         ", start: 0.5, duration: 1.0}\n  B2:\n    spring: {k: 50.0}\n    friction: " + friction +
         "\nsolver: {t_end: 1.0, gravity: [0.0, 0.0, -9.81], static_first: true}\noutput: {rate_hz: 0}\n";
}

// The arm of two_link_arm.urdf with this YAML.
Model ArmModel(const std::string& yaml_text) {
  const std::string yaml = testing::TempDir() + "friction_impulse.yaml";
  std::ofstream(yaml) << yaml_text;
  return BuildModel(LoadModelSpec(std::string(FLEXMBD_SOURCE_DIR) + "/test/data/urdf/two_link_arm.urdf", yaml));
}

// Runs `simulation` to t, from its static start first if `start`.
void StartAndRunTo(Simulation* simulation, double t, bool start = true) {
  const auto ignore = [](const OutputSample&) {};
  if (start) {
    simulation->SolveStaticStart();
    simulation->Begin(ignore);
  }
  simulation->AdvanceTo(t, simulation->model().solver().t_end, ignore);
}

// The second arm's impulsive motion from rest when the first turns at w1 about y at shoulder and elbow angles q1, q2,
// with friction of mu_s, mu_k on a race of radius rho at the elbow (the joint's reaction impulse P = m v_c is its
// normal impulse). Its angular momentum about the elbow, H(w2) = I w2 + m (r d2 x v_c(w2)) . y, is the friction's
// torque impulse T on it; stuck (w2 = w1) while |T| <= mu_s rho m |v_c(w1)|, else T = -mu_k rho m |v_c(w2)| s, s the
// slip's sign, the root lying between the stuck and the frictionless rates. The elbow's rate after, w2 - w1.
double ElbowRateAfter(double q1, double q2, double w1, double mu_s, double mu_k, double rho) {
  const Vec3 y = Vec3::UnitY();
  auto along = [](double angle) { return Vec3(std::cos(angle), 0.0, -std::sin(angle)); };  // x turned about y
  const Vec3 elbow = kFirstArm * along(q1), centre = kArm * along(q1 + q2);
  auto v_c = [&](double w2) -> Vec3 { return w1 * y.cross(elbow) + w2 * y.cross(centre); };
  auto H = [&](double w2) { return kInertia * w2 + kMass * centre.cross(v_c(w2)).dot(y); };
  const double stuck = H(w1);
  if (std::abs(stuck) <= mu_s * rho * kMass * v_c(w1).norm()) return 0.0;
  const double s = stuck < 0 ? 1.0 : -1.0;
  auto residual = [&](double w2) { return H(w2) + mu_k * rho * kMass * v_c(w2).norm() * s; };
  double a = w1, b = w1 - stuck / (kInertia + kMass * kArm * kArm);  // stuck, frictionless (H = 0)
  for (int k = 0; k < 200; ++k) {
    const double m = 0.5 * (a + b);
    (residual(m) > 0) == (residual(a) > 0) ? a = m : b = m;
  }
  return 0.5 * (a + b) - w1;
}

TEST(FrictionImpulse, StuckElbowTakesTheShouldersRateJumpByCoulombsLawForImpulses) {
  // Radius 1 m: the friction's impulse is of the order of the arm's. mu_s 0.3: the stuck arm needs T = -5.0 N m s
  // against a bound of 2.7 N m s, and slides; mu_s 1.0 bounds it at 9.0 N m s, and it stays stuck.
  struct Case {
    double mu_s, mu_k;
    int mode;
  };
  for (const Case& c : {Case{0.3, 0.2, FrictionEffect::kSlidingPositive}, Case{1.0, 0.8, FrictionEffect::kSticking}}) {
    SCOPED_TRACE(c.mu_s);
    const Model model = ArmModel(ArmYaml("{mu_s: " + std::to_string(c.mu_s) + ", mu_k: " + std::to_string(c.mu_k) +
                                         ", radius: 1.0, preload: 20.0}"));
    Simulation simulation(model);
    StartAndRunTo(&simulation, kJump);
    State state = simulation.state();
    ASSERT_DOUBLE_EQ(state.t, kJump);
    const int shoulder = model.FindVariable("B1"), elbow = model.FindVariable("B2");
    const int slot = model.friction_effects()[0]->slot();
    ASSERT_EQ(state.effects[slot].mode, FrictionEffect::kSticking);
    Eigen::VectorXd before = Eigen::VectorXd::Zero(model.num_variables()), after = before;
    after[shoulder] = kRate;
    SparseSystem system(model);
    VelocityProjection projection(model, &system);
    ASSERT_TRUE(projection.ApplyAtDriveJump(&state, before, after, 0.01));
    const double expected = ElbowRateAfter(state.q[shoulder], state.q[elbow], kRate, c.mu_s, c.mu_k, 1.0);
    // The limiting steps of 1e-6 and 2e-6 s extrapolated to zero leave O(h^2) of the rates; Newton at the default
    // 1e-6 leaves up to 1e-6 of the step's largest term, ~1e-5 rad/s of the 15 rad/s jump: 1e-5 rad/s (measured
    // 1.5e-9 and 7e-12). Without friction the elbow would turn at 14.957 rad/s, sliding it turns at 13.611 rad/s.
    // Released the way its round-off rate pointed, as before (F8), the sliding case missed this rate and kept the
    // stuck mode, and the stuck case's projection did not converge.
    EXPECT_NEAR(state.qdot[shoulder], kRate, 1e-5);
    EXPECT_NEAR(state.qdot[elbow], expected, 1e-5);
    EXPECT_EQ(state.effects[slot].mode, c.mode);
  }
}

// The user's model (test/data/yaml/arm_ramp_starts_under_elbow_friction.yaml) and the same arm with a sine started
// at its full rate, through the runner at default settings: both run to their end (both stopped at 0.5 s with "a
// defect of flexmbd", the breakaway's step limit (F3'') read the impulse as an acceleration 2 v / h and shrank the
// step with it), the elbow slides from the jump on, and the books close.
TEST(FrictionImpulse, ArmWhoseShoulderStartsAtARateUnderAStuckElbowRunsToItsEnd) {
  const std::string ramp = test::SourceText("test/data/yaml/arm_ramp_starts_under_elbow_friction.yaml");
  const std::string ramp_drive = "drive: {law: linear_ramp, value: -6.0, start: 0.5, duration: 1.0}";
  std::string sine = ramp;
  sine.replace(sine.find(ramp_drive), ramp_drive.size(),
               "drive: {law: sine, amplitude: -0.8, frequency: 1.0, start: 0.5}");  // -5.0 rad/s at 0.5 s
  for (const std::string& yaml : {ramp, sine}) {
    const std::string csv = testing::TempDir() + "friction_impulse.csv";
    std::string with_csv = yaml;
    with_csv.replace(with_csv.find("output: {rate_hz: 0}"), 20, "output: {rate_hz: 0, csv: " + csv + "}");
    const std::string output = test::RunnerOutput("test/data/urdf/two_link_arm.urdf", with_csv, "friction_impulse");
    SCOPED_TRACE(output);
    const test::CsvTable table = test::ReadCsv(csv);
    ASSERT_FALSE(table.rows.empty());
    auto at = [&](const std::vector<double>& row, const char* column) { return row.at(table.Column(column)); };
    EXPECT_DOUBLE_EQ(at(table.rows.back(), "t"), 1.0);
    double work = 0;
    bool slid_after_jump = false;
    for (const std::vector<double>& row : table.rows) {
      work = at(row, "friction.B2.work");
      if (at(row, "t") > kJump && !slid_after_jump) {
        // The first step after the jump: the second arm turns the other way than the first, and the elbow slips.
        slid_after_jump = at(row, "friction.B2.sticking") == 0.0 && at(row, "joint.B2.velocity") > 0.0;
        EXPECT_TRUE(slid_after_jump);
      }
    }
    EXPECT_GT(work, 0.0);
    // The books close to Newton's tolerance, 1e-6 of each step's largest term over its travel, partly cancelling over
    // the 160 and 190 steps (measured 7.7e-7 and 8.0e-8 of the energy through them; the frictionless arm 9.6e-8).
    const test::CsvBooks books = test::BooksAt(table, table.rows.back());
    EXPECT_LT(std::abs(books.imbalance), 2e-6 * books.throughput);
  }
}

// A set-point commanded at 0.5 s (the node's ~position_command) on the shoulder held at 0: the lag's rate jumps to
// (s - q) / tau = 6 rad/s there, the same impulse on the stuck elbow; the run reaches its end with the elbow slid.
TEST(FrictionImpulse, SetpointCommandedOverAStuckElbowRunsToItsEnd) {
  std::string text = ArmYaml("{mu_s: 0.3, mu_k: 0.2, radius: 0.02, preload: 20.0}");
  const std::string ramp = "{law: linear_ramp, value: " + std::to_string(kRate) + ", start: 0.5, duration: 1.0}";
  text.replace(text.find(ramp), ramp.size(), "{law: constant, value: 0.0}");
  const Model model = ArmModel(text);
  Simulation simulation(model);
  StartAndRunTo(&simulation, kJump);
  simulation.SetSetpoint(model.FindVariable("B1"), 0.6, 0.1);
  ASSERT_NO_THROW(StartAndRunTo(&simulation, model.solver().t_end, false));
  EXPECT_DOUBLE_EQ(simulation.state().t, model.solver().t_end);
  EXPECT_GT(simulation.state().effects[model.friction_effects()[0]->slot()].work, 0.0);
}

}  // namespace friction_impulse_test
}  // namespace flexmbd
