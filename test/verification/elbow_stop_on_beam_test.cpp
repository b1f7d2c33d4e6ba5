// An elastic stop on a joint at a beam's tip (docs/theory.md, (C5) and (C6)), through the runner: a rigid forearm
// falls 0.05 rad onto the elbow's Hertz stop at the tip of a flexible upper arm (test/data/urdf/flex_arm_elbow.urdf,
// the beam without rotary inertia). The elbow's variable carries the alternating mode of the beam tip's rotation,
// which moves it by a finite amount however short the step: the landings before the stop (C5) and the budget of
// the contact's first step (C6) were redone below dt_min ("a stop or friction event could not be stepped across")
// at the contact radius 1 m (t = 0.1326 s) and 20 m (0.0647 s). At dt_min the contact now begins where it is. (Later,
// at 0.184 s inside a contact (its budget (C6)) and at 0.077 s (the local error test (T12)) the same joint asked
// for steps below dt_min; both radii now run to 1 s, docs/theory.md "Algebraic rotations".)

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../integration/helpers/csv_table.hpp"
#include "csv_books.hpp"
#include "runner_output.hpp"
#include "yaml_text.hpp"

namespace flexmbd {
namespace elbow_stop_on_beam_test {

// The arm released straight, the shoulder held by its drive or free (`shoulder` its YAML entry); the elbow's lossless
// Hertz stops at the URDF's <limit>, with the contact radius `radius` [m].
std::string ArmYaml(const std::string& shoulder, const std::string& radius, const std::string& t_end,
                    const std::string& csv) {
  return "beams:\n"
         "  upper: {length: 1.0, elements: 3, section: {EA: 1.0e8, GA2: 4.0e7, GA3: 4.0e7, GJ: 400.0, EI2: 500.0,\n"
         "          EI3: 500.0, m: 2.0}}\n"
         "joints:\n"
         + shoulder +
         "  elbow: {backlash: {radius_lower: " + radius + ", radius_upper: " + radius +
         ", stop: {type: elastic, law: hertz, stiffness: 1.0e7}}}\n"
         "solver: {t_end: " + t_end + "}\n"
         "output: {csv: " + csv + "}\n";
}

// Runs to t_end at default settings and checks the books (T6) on every sample: the stop is lossless and nothing
// else dissipates, so what the scheme removes is booked as numerical dissipation and the books close to Newton's
// tolerance (solver.tol, 1e-6) times the energy through them, as in the other runner cases.
void ExpectRunsWithClosedBooks(const std::string& shoulder, const std::string& radius, const std::string& t_end,
                               const std::string& stop, const std::string& name) {
  const std::string csv = testing::TempDir() + name + ".csv";
  const std::string yaml = ArmYaml(shoulder, radius, t_end, csv);
  const std::string out = test::RunnerOutput("test/data/urdf/flex_arm_elbow.urdf", yaml, name);
  EXPECT_NE(out.find("finished at t = " + t_end + " s"), std::string::npos) << out;
  // The forearm reached the stop it falls onto.
  EXPECT_EQ(out.find("stop elbow " + stop + ": 0 contact"), std::string::npos) << out;
  EXPECT_NE(out.find("stop elbow " + stop + ": "), std::string::npos) << out;
  const test::CsvTable table = test::ReadCsv(csv);
  ASSERT_FALSE(table.rows.empty());
  const double worst = test::WorstImbalance(table);
  testing::Test::RecordProperty("books_per_throughput_1e-9", std::to_string(worst * 1e9));
  EXPECT_LE(worst, 1.0e-6);
}

TEST(ElbowStopOnBeam, ContactRadiusOneMetreStepsIntoTheSecondContact) {
  // Gravity turns the forearm toward positive angles, onto the upper stop.
  ExpectRunsWithClosedBooks("  shoulder: {drive: {law: constant, value: 0.0}}\n", "1.0", "0.14", "upper",
                            "elbow_stop_radius_1");
}

TEST(ElbowStopOnBeam, ContactRadiusTwentyMetresStepsIntoTheContact) {
  // The shoulder free: the whole arm falls, and the forearm, left behind, meets the lower stop.
  ExpectRunsWithClosedBooks("", "20.0", "0.075", "lower", "elbow_stop_radius_20");
}

// The 1 m arm to 1 s at default settings (52 contacts with the upper stop).
// The tip node's rotation, which no rotary inertia holds, is algebraic: the midpoint equations leave it an
// alternating error (1e-7 to 6e-7 rad) that moves the elbow by a finite amount however short the step. It stopped the
// runs at 0.184 s (radius 1 m, the budget (C6) of a contact's first step read the error as a change of rate) and at
// 0.077 s (20 m, the onset's error (C6')); the local error test (T12) read it as a third derivative and held the steps
// near 1e-5 s after the first impact (4,956 steps to 0.141 s, 571 now).
TEST(ElbowStopOnBeam, ContactRadiusOneMetreRunsToOneSecondAtDefaultSettings) {
  ExpectRunsWithClosedBooks("  shoulder: {drive: {law: constant, value: 0.0}}\n", "1.0", "1", "upper",
                            "elbow_stop_radius_1_to_1s");
}

// The 20 m arm is not tested to 1 s: it stops near 0.2 s at most tolerances, Newton failing in a resting contact
// (docs/theory.md, "Algebraic rotations").

// A static analysis of the arm started straight, its shoulder held, the elbow's rigid stops open: the forearm's hinge
// is at a dead point (gravity gives it no stiffness) and the beam's nodes have no rotary inertia, so the model released
// from rest has no accelerations to tell the load's direction by. It stopped with "singular iteration matrix after 1
// Newton iteration(s)"; now the nearest stop is closed, the lower one pulls and is released, and the forearm rests on
// the upper one (docs/theory.md, "Static increments").
TEST(ElbowStopOnBeam, StaticAnalysisFromStraightRestsOnTheRigidStopTheForearmFallsTo) {
  const std::string csv = testing::TempDir() + "elbow_static.csv";
  std::string yaml = ArmYaml("  shoulder: {drive: {law: constant, value: 0.0}}\n", "1.0", "0.0", csv);
  yaml = test::Replaced(yaml, "type: elastic, law: hertz, stiffness: 1.0e7", "type: rigid");
  yaml = test::Replaced(yaml, "solver: {t_end: 0.0}", "solver: {analysis: static}");
  test::RunnerOutput("test/data/urdf/flex_arm_elbow.urdf", yaml, "elbow_static");
  const test::CsvTable table = test::ReadCsv(csv);
  ASSERT_FALSE(table.rows.empty());
  const std::vector<double>& row = table.rows.back();
  // On the upper stop at 0.05 rad to the constraint tolerance (1e-11 m of gap at the radius of 1 m).
  EXPECT_NEAR(row[table.Column("joint.elbow.position")], 0.05, 1.0e-10);
  EXPECT_EQ(row[table.Column("stop.elbow.upper.in_contact")], 1.0);
  EXPECT_EQ(row[table.Column("stop.elbow.lower.in_contact")], 0.0);
  // The stop carries the forearm's weight moment m g d cos(0.05 + theta) about the elbow, theta the beam tip's droop
  // under its own weight w, the forearm's weight P and that moment M (cantilever, EI 500 N m^2, L 1 m):
  // theta = w L^3 / (6 EI) + P L^2 / (2 EI) + M L / EI, solved with M by fixed point. Three elements with lumped mass
  // (B6) and small deflections change theta by less than 1e-4 rad (the droop is 0.021 rad), the torque by less than
  // tan(0.071) 1e-4 = 7e-6 of it.
  constexpr double kG = 9.81, kEI = 500.0, kWeight = 1.0 * kG, kArm = 0.25, kBeamWeight = 2.0 * kG;
  double moment = kWeight * kArm;
  for (int k = 0; k < 50; ++k) {
    const double theta = kBeamWeight / (6 * kEI) + kWeight / (2 * kEI) + moment / kEI;
    moment = kWeight * kArm * std::cos(0.05 + theta);
  }
  const double torque = -row[table.Column("stop.elbow.upper.torque")];
  testing::Test::RecordProperty("torque_relative_error_1e-9", std::to_string((torque / moment - 1) * 1e9));
  EXPECT_NEAR(torque, moment, 2.0e-5 * moment);
}

// The same static analysis with the elbow's Hertz stops: an elastic stop has no row to close, and without the
// accelerations the load cannot tell which stop the forearm rests on. It ended with the bare "singular iteration
// matrix"; the runner's failure (exit 3) now names the joint, why nothing holds it and what to do.
TEST(ElbowStopOnBeam, StaticAnalysisOnElasticStopsWithoutInertiaNamesTheJointAndWhatToDo) {
  std::string yaml = ArmYaml("  shoulder: {drive: {law: constant, value: 0.0}}\n", "1.0", "0.0",
                             testing::TempDir() + "elbow_static_elastic.csv");
  yaml = test::Replaced(yaml, "solver: {t_end: 0.0}", "solver: {analysis: static}");
  const std::string out = test::RunnerOutput("test/data/urdf/flex_arm_elbow.urdf", yaml, "elbow_static_elastic", 3);
  EXPECT_NE(out.find("joint elbow has no stiffness, nothing holds it; only its elastic stops could"),
            std::string::npos)
      << out;
  for (const char* remedy : {"m_ii", "use rigid stops", "start the joint on the stop", "dynamic analysis"}) {
    EXPECT_NE(out.find(remedy), std::string::npos) << remedy << " not in: " << out;
  }
}

}  // namespace elbow_stop_on_beam_test
}  // namespace flexmbd
