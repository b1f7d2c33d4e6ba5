// Short events of time functions after a long rest, through the runner and YAML at default settings, as a user meets
// them: the steps grow to dt_max at rest, and once stepped over a 12 ms load pulse and a 20 ms drive blip at
// t = 100 s (no motion at all, external work 0). The steps land on the time functions' breakpoints (docs/theory.md,
// "Breakpoints").

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "../integration/helpers/csv_table.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace time_function_breakpoints_test {

// test/data/urdf/pend_rev.urdf: a 1 kg bob 1 m below a hinge about y, I_yy 1e-4 kg m^2 about its centre.
constexpr double kMass = 1.0, kLever = 1.0, kGravity = 9.81;
constexpr double kInertia = kMass * kLever * kLever + 1.0e-4;  // about the hinge [kg m^2]

// Runs `yaml` (output at `rate_hz` to a CSV appended) on the pendulum; returns the CSV.
test::CsvTable RunPendulum(const std::string& yaml, int rate_hz, const std::string& name) {
  const std::string csv = testing::TempDir() + name + ".csv";
  const std::string out = test::RunnerOutput(
      "test/data/urdf/pend_rev.urdf", yaml + "output: {rate_hz: " + std::to_string(rate_hz) + ", csv: " + csv + "}\n",
      name);
  EXPECT_NE(out.find("finished at t = "), std::string::npos) << out;
  return test::ReadCsv(csv);
}

double At(const test::CsvTable& table, size_t row, const std::string& column) {
  return table.rows.at(row).at(table.Column(column));
}

// A 100 N push along x on the bob at rest for 100 s, by a table: 1 ms up, 10 ms held, 1 ms down, an impulse
// J = 100 N x 11 ms = 1.1 N s and an angular impulse J l about the hinge. The bob leaves at the rate J l / I and
// swings to m g l (1 - cos(theta)) = W, the pulse's work W = (J l)^2 / (2 I).
TEST(TimeFunctionBreakpoints, AShortLoadPulseAfterALongRestGivesItsImpulseWorkAndSwing) {
  const test::CsvTable table = RunPendulum(
      "loads:\n"
      "  - {body: bob, force: [100.0, 0.0, 0.0], point: [0.0, 0.0, -1.0], scale: {law: table,"
      " times: [100.0, 100.001, 100.011, 100.012], values: [0.0, 1.0, 1.0, 0.0]}}\n"
      "solver: {t_end: 101.0}\n",
      100, "breakpoint_pulse");
  ASSERT_GT(table.rows.size(), 10000u);
  const double angular_impulse = 100.0 * 0.011 * kLever;
  const double rate = angular_impulse / kInertia;
  const double work = 0.5 * angular_impulse * angular_impulse / kInertia;
  const double swing = std::acos(1.0 - work / (kMass * kGravity * kLever));
  // The pulse's work and the books: the bob turns by at most 0.013 rad during the pulse, so the lever of the push
  // (cos) and gravity's moment over it move the work by about 1e-4 of itself; the bound is 5e-4.
  constexpr double kWorkTolerance = 5.0e-4;
  const size_t last = table.rows.size() - 1;
  EXPECT_NEAR(At(table, last, "energy.external_work"), work, kWorkTolerance * work);
  EXPECT_NEAR(At(table, last, "energy.total") - At(table, 0, "energy.total") + At(table, last, "energy.dissipated") +
                  At(table, last, "energy.numerical_dissipation"),
              work, kWorkTolerance * work);
  double peak_rate = 0, peak_angle = 0;
  for (size_t i = 0; i < table.rows.size(); ++i) {
    peak_rate = std::max(peak_rate, std::abs(At(table, i, "joint.pivot.velocity")));
    peak_angle = std::max(peak_angle, std::abs(At(table, i, "joint.pivot.position")));
  }
  // The fastest sample is the first after the pulse, 8 ms after its end at 0.015 rad: gravity slowed the bob by
  // g theta t / l = 1.2e-3 rad/s, 1.1e-3 of the rate, since the pulse; the bound is 2e-3.
  constexpr double kRateTolerance = 2.0e-3;
  EXPECT_NEAR(peak_rate, rate, kRateTolerance * rate);
  // The samples every 10 ms miss the top of the swing by at most 5 ms: 1 - cos(w 5 ms) = 1.2e-4 of it at w = 3.1
  // rad/s; the work's 5e-4 moves the angle by about half that; the bound is 1e-3.
  constexpr double kSwingTolerance = 1.0e-3;
  EXPECT_NEAR(peak_angle, swing, kSwingTolerance * swing);
}

// The hinge driven by a table: at rest for 100 s, then a 0.1 rad blip, up in 10 ms and down in 10 ms. A driven
// variable follows f(t) exactly at the ends of its steps, and the samples between them interpolate linearly, which
// is exact on the table's linear pieces once the steps land on its abscissae.
TEST(TimeFunctionBreakpoints, ADriveTableBlipAfterALongRestIsFollowed) {
  const test::CsvTable table = RunPendulum("joints: {pivot: {drive: {law: table, times: [100.0, 100.01, 100.02],"
                                           " values: [0.0, 0.1, 0.0]}}}\n"
                                           "solver: {t_end: 100.05}\n",
                                           1000, "breakpoint_drive_blip");
  // Sample times are t_0 + k / rate (round-off 1e-14 s at 100 s, times the slope 10 rad/s) and the drive constraint
  // is met to Newton's tolerance relative to O(1) residuals: 1e-9 rad bounds both.
  constexpr double kFollowed = 1.0e-9;
  ASSERT_EQ(table.rows.size(), 100051u);
  for (size_t row = 99990; row < table.rows.size(); ++row) {
    const double t = At(table, row, "t");
    const double blip = std::max(0.0, 0.1 - 10.0 * std::abs(t - 100.01));
    EXPECT_NEAR(At(table, row, "joint.pivot.position"), blip, kFollowed) << "t " << t;
  }
  // Held at rest after the blip: the steps from its kinks start from velocities carried across the drive's rate
  // jumps (docs/theory.md (T13)), so no alternating rate of the jumps is left (it read -23 rad/s at the end, 477 J).
  const size_t last = table.rows.size() - 1;
  EXPECT_NEAR(At(table, last, "joint.pivot.velocity"), 0.0, kFollowed / 0.01);
  EXPECT_NEAR(At(table, last, "energy.kinetic"), 0.0, kFollowed);
}

}  // namespace time_function_breakpoints_test
}  // namespace flexmbd
