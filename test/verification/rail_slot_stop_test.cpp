// Rigid stops and Coulomb friction on a slot at a flexible rail's tip, through the runner at default settings
// (test/data/yaml/rail_slot_rigid_stops_friction.yaml, explore6 D3). A rigid impact there is one between the slider and
// the rail's tip node alone: it sets off the rail's axial vibration (near 1e4 rad/s), which turns the slip at the slot
// through zero again and again at accelerations near 5e4 m/s^2. The rule near sticking (F5), whose steps are v0 / |a|,
// then asked for steps below dt_min, and the run stopped at its first impact, t = 0.171637 s ("step size fell below
// dt_min"). It now runs through the impacts on both stops (docs/theory.md, (F5)).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../integration/helpers/csv_table.hpp"
#include "csv_books.hpp"
#include "runner_output.hpp"
#include "yaml_text.hpp"

namespace flexmbd {
namespace rail_slot_stop_test {

// The step that begins a contact with `stop`, read from a CSV of every step: its size, the slot's rates at its start
// and end, and the stop's impulse over it (the step's force times its size).
struct Impact {
  double t_start = std::nan(""), h = 0, rate_before = 0, rate_after = 0, impulse = 0;
};

Impact FirstImpact(const test::CsvTable& table, const std::string& stop) {
  const size_t contact = table.Column("stop.slot." + stop + ".in_contact");
  const size_t force = table.Column("stop.slot." + stop + ".force");
  const size_t rate = table.Column("joint.slot.velocity");
  Impact impact;
  for (size_t k = 1; k < table.rows.size(); ++k) {
    const std::vector<double>& before = table.rows[k - 1];
    const std::vector<double>& row = table.rows[k];
    if (row[contact] != 1.0) continue;
    impact.t_start = before[0];
    impact.h = row[0] - before[0];
    impact.rate_before = before[rate];
    impact.rate_after = row[rate];
    impact.impulse = row[force] * impact.h;
    return impact;
  }
  return impact;
}

// Where a run named `name` writes its CSV.
std::string CsvPath(const std::string& name) { return testing::TempDir() + name + ".csv"; }

// The YAML with its solver settings replaced by `solver`, writing the CSV of every step for the run named `name`.
std::string RailYaml(const std::string& solver, const std::string& name) {
  const std::string yaml = test::SourceText("test/data/yaml/rail_slot_rigid_stops_friction.yaml");
  const std::string solved = test::Replaced(yaml, "solver: {t_end: 0.5, static_first: true}", solver);
  return test::Replaced(solved, "output: {rate_hz: 0}", "output: {rate_hz: 0, csv: " + CsvPath(name) + "}");
}

// Runs the YAML text, expecting it to finish at `t_end`; returns its CSV.
test::CsvTable RunRail(const std::string& yaml, const std::string& t_end, const std::string& name) {
  const std::string output = test::RunnerOutput("test/data/urdf/rail_slot.urdf", yaml, name);
  EXPECT_NE(output.find("finished at t = " + t_end + " s"), std::string::npos) << output;
  return test::ReadCsv(CsvPath(name));
}

// An impact is one between the slider (1 kg) and the rail's tip node alone, which carries 1/8 of the last cubic
// element's mass (B6), 5 kg / 3 / 8: the stop's impulse changes the slot's rate by J / m_r, m_r their reduced mass.
// The other forces on the two over the contact step (the rail's axial force, near 10 N; friction is held) add under
// 1e-4 N s to the 0.16-0.19 N s of the impulse in a step shorter than 1e-5 s: a bound of 1e-3 (measured 1.2e-5 at the
// default error_tol, 2e-8 at 1e-6). (The rebound itself is the scheme's, (C3): 1 in the default run's first impact,
// 0.83 at error_tol 1e-6, where alpha is on.)
void ExpectImpulseOfTheTipNode(const Impact& impact) {
  const double tip_mass = 5.0 / 3.0 / 8.0, reduced_mass = tip_mass / (1.0 + tip_mass);
  EXPECT_LT(impact.h, 1.0e-5);
  const double change = std::abs(impact.rate_after - impact.rate_before);
  EXPECT_NEAR(std::abs(impact.impulse), reduced_mass * change, 1.0e-3 * reduced_mass * change);
}

// Friction's work never falls, and the books close to Newton's tolerance on every step (1e-6 of the throughput, as
// in the other runner cases; measured 1e-8).
void ExpectFrictionWorkAndBooks(const test::CsvTable& table) {
  EXPECT_EQ(test::LargestFall(table, "friction.slot.work"), 0.0);
  EXPECT_GT(table.rows.back().at(table.Column("friction.slot.work")), 0.0);
  const double worst = test::WorstImbalance(table);
  testing::Test::RecordProperty("books_per_throughput_1e-9", std::to_string(worst * 1e9));
  EXPECT_LE(worst, 1.0e-6);
}

TEST(RailSlotStop, SliderStrikesBothStopsOfASlotOnAFlexibleRailAtDefaultSettings) {
  const test::CsvTable table = RunRail(RailYaml("solver: {t_end: 0.5, static_first: true}", "rail_slot"), "0.5",
                                       "rail_slot");
  ASSERT_GT(table.rows.size(), 2u);
  // The first impact on the upper stop: where a run at error_tol 1e-6 and dt_min 1e-10 begins it (0.171654 s; the
  // hand figure on a rigid rail, 0.171686 s, is 3.2e-5 s later, from the breakaway that run books 9.6e-5 s before
  // t_b). Measured 0.171620 s; the error follows error_tol (3.5e-4, 4.8e-5, 1.3e-5, 1e-6 s at 1e-3, 3e-4, 3e-5,
  // 1e-5), and 1e-4 s leaves a margin of 3 at the default, as for the four-bar's impact (StickingLoop).
  const Impact upper = FirstImpact(table, "upper");
  EXPECT_NEAR(upper.t_start, 0.171654, 1.0e-4);
  // Approach speed against the hand figure x'' = A w^2 sin(w t) - mu g from t_b (0.515054 m/s; the rail's stretch
  // under the slider, 1e-7 m, changes it by far less): within 1e-3 of it (measured 1.2e-5; 2.3e-4 at error_tol 1e-6,
  // whose breakaway is early).
  EXPECT_NEAR(upper.rate_before, 0.515054, 1.0e-3 * 0.515054);
  ExpectImpulseOfTheTipNode(upper);
  // The slider, rebounding, reaches the lower stop (near 0.46 s; where depends on the scheme's rebound, (C3), and on
  // its damping of the rail's vibration, and follows no tolerance: docs/theory.md (F5)).
  const Impact lower = FirstImpact(table, "lower");
  ASSERT_FALSE(std::isnan(lower.t_start));
  EXPECT_GT(lower.t_start, upper.t_start);
  ExpectImpulseOfTheTipNode(lower);
  ExpectFrictionWorkAndBooks(table);
}

// At error_tol 1e-6 (dt_min 1e-9 by default) the slider, stuck for a moment between the rail's axial vibrations, had
// the breakaway located (F3') down to 8.7e-10 s, and the run stopped at 0.171741 s, after its first impact: a step
// of dt_min now breaks away where it is. The first impact begins where the run at error_tol 1e-5 has it (0.171655 s),
// within 1e-5 s (the error falls with the tolerance: 3.4e-5 s at 1e-4, 1e-6 s at 1e-5; measured 1e-6 s).
TEST(RailSlotStop, AtErrorTolOneInAMillionTheSliderRunsOnAfterItsFirstImpact) {
  const std::string name = "rail_slot_tight";
  const test::CsvTable table =
      RunRail(RailYaml("solver: {t_end: 0.2, static_first: true, error_tol: 1.0e-6}", name), "0.2", name);
  ASSERT_GT(table.rows.size(), 2u);
  const Impact upper = FirstImpact(table, "upper");
  EXPECT_NEAR(upper.t_start, 0.171655, 1.0e-5);
  ExpectImpulseOfTheTipNode(upper);
  ExpectFrictionWorkAndBooks(table);
}

// A rail ten times as stiff along its length (EA 1e9 N): the slip turns at 1.6e5 m/s^2 after an impact, within a step
// of dt_min from faster than a capture, and the landing on its reversal (F2) asked for 9.3e-8 s at 0.957596 s: a step
// of dt_min now keeps the slide's mode. To 1 s at default settings, through impacts on both stops (the tip node's mass
// is the same).
TEST(RailSlotStop, AStifferRailRunsToOneSecondAtDefaultSettings) {
  const std::string name = "rail_slot_stiff";
  const std::string yaml = RailYaml("solver: {t_end: 1.0, static_first: true}", name);
  const test::CsvTable table = RunRail(test::Replaced(yaml, "EA: 1.0e8", "EA: 1.0e9"), "1", name);
  ASSERT_GT(table.rows.size(), 2u);
  for (const char* stop : {"upper", "lower"}) {
    const Impact impact = FirstImpact(table, stop);
    ASSERT_FALSE(std::isnan(impact.t_start)) << stop;
    ExpectImpulseOfTheTipNode(impact);
  }
  ExpectFrictionWorkAndBooks(table);
}

}  // namespace rail_slot_stop_test
}  // namespace flexmbd
