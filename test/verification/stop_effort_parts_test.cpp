// The parts of a joint's effort (docs/ros.md, "Effort"): inside an elastic contact the effort is the stop's torque
// plus the friction torque, sample by sample, run the user's way (flexmbd_run, CSV). The stop columns once held
// V'(a_f) at the end of the step instead of the step's discrete-gradient force (C2b) that the effort holds: 4 N m
// off at an effort of 166 N m.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "../integration/helpers/csv_table.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace stop_effort_parts_test {

// hbeam.urdf: a flexible blade (1 m, 2 kg/m) hinged at its root, released at -0.5 rad onto a droop stop at 0 of
// radius 0.1 m, on a frictional hinge, every step sampled into `csv`.
std::string BladeOnStop(const std::string& stop, const std::string& csv) {
  return "beams:\n"
         "  blade: {length: 1.0, elements: 4, damping: 1.0e-4, section: {EA: 1.0e8, GA2: 1.0e7, GA3: 1.0e7, GJ: 1.0e3,"
         " EI2: 1.0e3, EI3: 1.0e3, m: 2.0, m_ii: [1.0e-3, 1.0e-5, 1.0e-5]}}\n"
         "joints:\n"
         "  hinge:\n"
         "    initial: {position: -0.5}\n"
         "    friction: {mu_k: 0.1, mu_s: 0.15, radius: 0.02, preload: 20.0}\n"
         "    backlash: {upper: 0.0, radius_upper: 0.1, stop: " + stop + "}\n"
         "solver: {t_end: 0.4, dt: 1.0e-3}\n"
         "output: {rate_hz: 0, csv: " + csv + "}\n";
}

// On every sample in contact, effort = stop torque + friction torque. The effort is the hinge's G_q^T lambda, which
// balances the effects on the variable's row to Newton's tolerance (solver.tol, 1e-6, relative to the row's
// largest term, the contact's at most the peak effort): measured 1.5e-7 N m at a peak of 166 N m.
void ExpectEffortIsTheSumOfItsParts(const std::string& stop, const std::string& name) {
  constexpr double kNewtonTolerance = 1.0e-6;
  const std::string csv = testing::TempDir() + name + ".csv";
  const std::string out = test::RunnerOutput("test/data/urdf/hbeam.urdf", BladeOnStop(stop, csv), name);
  const test::CsvTable table = test::ReadCsv(csv);
  ASSERT_FALSE(table.rows.empty()) << out;
  const size_t effort = table.Column("joint.hinge.effort"), contact = table.Column("stop.hinge.upper.in_contact");
  const size_t stop_torque = table.Column("stop.hinge.upper.torque"), friction = table.Column("friction.hinge.torque");
  double peak = 0;
  for (const std::vector<double>& row : table.rows) peak = std::max(peak, std::abs(row[effort]));
  int in_contact = 0;
  for (const std::vector<double>& row : table.rows) {
    if (row[contact] == 0.0) continue;
    ++in_contact;
    EXPECT_NEAR(row[effort], row[stop_torque] + row[friction], kNewtonTolerance * peak) << "t = " << row[0];
  }
  EXPECT_GT(in_contact, 10) << out;
}

TEST(StopEffortParts, HertzStopAndFrictionSumToTheEffortInsideAContact) {
  ExpectEffortIsTheSumOfItsParts("{type: elastic, law: hertz, stiffness: 1.0e9, restitution: 0.7}", "parts_hertz");
}

TEST(StopEffortParts, LinearStopAndFrictionSumToTheEffortInsideAContact) {
  ExpectEffortIsTheSumOfItsParts("{type: elastic, law: linear, stiffness: 1.0e7, restitution: 0.7}", "parts_linear");
}

}  // namespace stop_effort_parts_test
}  // namespace flexmbd
