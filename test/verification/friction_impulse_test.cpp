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

// Runs the arm of two_link_arm.urdf with `yaml` (which has `output: {rate_hz: 0}`) through the runner, its samples
// written to a CSV named after `name`; the runner's output in *output, the samples as returned.
test::CsvTable RunArm(const std::string& yaml, const std::string& name, std::string* output) {
  const std::string csv = testing::TempDir() + name + ".csv";
  std::string with_csv = yaml;
  with_csv.replace(with_csv.find("output: {rate_hz: 0}"), 20, "output: {rate_hz: 0, csv: " + csv + "}");
  *output = test::RunnerOutput("test/data/urdf/two_link_arm.urdf", with_csv, name);
  return test::ReadCsv(csv);
}

// The second arm's impulsive motion when the first's rate jumps from w1_0 to w1 about y at shoulder and elbow angles
// q1, q2, the second turning at w2_0 (absolute) before, with friction of mu_s, mu_k on a race of radius rho at the
// elbow. The elbow's reaction impulse on the second arm, P = m (v_c - v_c0), is the normal impulse, and the change of
// the second arm's angular momentum about the elbow, T(w2) = H(w1, w2) - H(w1_0, w2_0) with H = I w2 + m (r x v_c) . y,
// the friction's torque impulse. Stuck (w2 = w1) while |T(w1)| <= mu_s rho |P(w1)|, else sliding with T = -mu_k rho |P|
// s, s the sign of the slip after, the root lying between the stuck and the frictionless rates. The elbow's rate
// after, w2 - w1.
struct ArmJump {
  double q1, q2, w1_0, w2_0, w1;
};
double ElbowRateAfter(const ArmJump& jump, double mu_s, double mu_k, double rho) {
  const Vec3 y = Vec3::UnitY();
  auto along = [](double angle) { return Vec3(std::cos(angle), 0.0, -std::sin(angle)); };  // x turned about y
  const Vec3 elbow = kFirstArm * along(jump.q1), centre = kArm * along(jump.q1 + jump.q2);
  auto v_c = [&](double w1, double w2) -> Vec3 { return w1 * y.cross(elbow) + w2 * y.cross(centre); };
  auto H = [&](double w1, double w2) { return kInertia * w2 + kMass * centre.cross(v_c(w1, w2)).dot(y); };
  auto T = [&](double w2) { return H(jump.w1, w2) - H(jump.w1_0, jump.w2_0); };
  auto P = [&](double w2) { return kMass * (v_c(jump.w1, w2) - v_c(jump.w1_0, jump.w2_0)).norm(); };
  const double stuck = T(jump.w1);
  if (std::abs(stuck) <= mu_s * rho * P(jump.w1)) return 0.0;
  const double s = stuck < 0 ? 1.0 : -1.0;
  auto residual = [&](double w2) { return T(w2) + mu_k * rho * P(w2) * s; };
  double a = jump.w1, b = jump.w1 - stuck / (kInertia + kMass * kArm * kArm);  // stuck, frictionless (T = 0)
  for (int k = 0; k < 200; ++k) {
    const double m = 0.5 * (a + b);
    (residual(m) > 0) == (residual(a) > 0) ? a = m : b = m;
  }
  return 0.5 * (a + b) - jump.w1;
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
    const ArmJump jump{state.q[shoulder], state.q[elbow], 0.0, 0.0, kRate};
    const double expected = ElbowRateAfter(jump, c.mu_s, c.mu_k, 1.0);
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
    std::string output;
    const test::CsvTable table = RunArm(yaml, "friction_impulse", &output);
    SCOPED_TRACE(output);
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

// The elbow sliding into the jump (F8): test/data/yaml/arm_ramp_turns_a_sliding_elbow.yaml, the arm released with its
// elbow turning at 3 rad/s, friction on a race of 0.3 m, the shoulder starting a ramp at +6 rad/s at 0.02 s, through
// the runner at default settings. The jump turns the elbow back, from 3.19 rad/s to -11.79 without friction; the
// impulse that stops it, about 3.9 N m s, is within mu_s rho times the normal impulse with mu_s 3.0 (6.7 N m s), and
// the elbow stays stuck; with mu_s 1.0 (2.2 N m s) it slides back, to -10.08 rad/s. Kept sliding forward across the
// jump, as before, its friction pushed it on the way the jump turned it: -12.64 rad/s for both (the samples' line at
// the jump, as below), which this test refused.
TEST(FrictionImpulse, ElbowSlidingIntoTheShouldersRateJumpSticksOrSlidesBackByCoulombsLawForImpulses) {
  constexpr double kStart = 0.02, kUp = 6.0, kRace = 0.3, kMuK = 0.8;  // [s, rad/s, m, -]: the YAML's
  const std::string three = test::SourceText("test/data/yaml/arm_ramp_turns_a_sliding_elbow.yaml");
  std::string one = three;
  one.replace(one.find("mu_s: 3.0"), 9, "mu_s: 1.0");
  for (const auto& [mu_s, yaml] : {std::pair{3.0, three}, std::pair{1.0, one}}) {
    SCOPED_TRACE(mu_s);
    std::string output;
    const test::CsvTable table = RunArm(yaml, "sliding_elbow", &output);
    SCOPED_TRACE(output);
    auto at = [&](size_t row, const char* column) { return table.rows.at(row).at(table.Column(column)); };
    size_t jump_row = 0;
    while (jump_row < table.rows.size() && at(jump_row, "t") < kStart) ++jump_row;
    ASSERT_LT(jump_row + 3, table.rows.size());
    ASSERT_DOUBLE_EQ(at(jump_row, "t"), kStart);  // a step ends at the jump: its sample is the state before it
    ASSERT_GT(at(jump_row, "joint.B2.velocity"), 0.0);
    ASSERT_EQ(at(jump_row, "friction.B2.sticking"), 0.0);
    const double w1_0 = at(jump_row, "joint.B1.velocity");
    const ArmJump jump{at(jump_row, "joint.B1.position"), at(jump_row, "joint.B2.position"), w1_0,
                       w1_0 + at(jump_row, "joint.B2.velocity"), kUp};
    const double expected = ElbowRateAfter(jump, mu_s, kMuK, kRace);
    // The samples after the jump are a step apart (0.01 s, over which the rate changes by ~0.6 rad/s): the rate
    // just after it is their line extrapolated back to it, whose error is about v'' h1 (h1 + h2) / 2, v'' taken from
    // the three samples after the jump; twice that, and the projection's 1e-5 (above).
    const double t1 = at(jump_row + 1, "t"), t2 = at(jump_row + 2, "t"), t3 = at(jump_row + 3, "t");
    const double v1 = at(jump_row + 1, "joint.B2.velocity"), v2 = at(jump_row + 2, "joint.B2.velocity"),
                 v3 = at(jump_row + 3, "joint.B2.velocity");
    const double after_jump = v1 - (v2 - v1) * (t1 - kStart) / (t2 - t1);
    const double curvature = 2.0 * ((v3 - v2) / (t3 - t2) - (v2 - v1) / (t2 - t1)) / (t3 - t1);
    const double bound = std::abs(curvature) * (t1 - kStart) * (t2 - kStart) + 1e-5;
    EXPECT_NEAR(after_jump, expected, bound);
    EXPECT_EQ(at(jump_row + 1, "friction.B2.sticking"), expected == 0.0 ? 1.0 : 0.0);
    EXPECT_DOUBLE_EQ(at(table.rows.size() - 1, "t"), 0.1);
    // The books close as in the runs above.
    const test::CsvBooks books = test::BooksAt(table, table.rows.back());
    EXPECT_LT(std::abs(books.imbalance), 2e-6 * books.throughput);
  }
}

}  // namespace friction_impulse_test
}  // namespace flexmbd
