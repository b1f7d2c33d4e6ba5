// Beam-station outputs between steps, through the runner and YAML as a user reads them: Simo and Vu-Quoc's blade
// (1986) spun up to 4 rad/s, sampled at 100 Hz. The samples interpolated linearly between the steps: the rotation
// vector across its +-pi branch cut (samples read ~0 where the blade stood at pi) and the tip's position along the
// chord (2.2 mm inside its circle, a centrifugal stretch of -1.26 mm against +0.229 mm). Joint variables between
// steps likewise: read linearly, they carried up to h^2 |q''| / 8.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../integration/helpers/csv_table.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace beam_station_interpolation_test {

constexpr double kPi = 3.14159265358979323846;
// The blade: L 10 m, EA 2.8e7 N, m 1.2 kg/m; the hub's rate ramps to Omega = 4 rad/s over 15 s.
constexpr double kLength = 10.0, kEA = 2.8e7, kMassPerLength = 1.2, kOmega = 4.0;

// An angle brought to [-pi, pi).
double Wrapped(double angle) { return angle - 2.0 * kPi * std::floor((angle + kPi) / (2.0 * kPi)); }

TEST(BeamStationInterpolation, SamplesOfASpinningBladeFollowItsCircleAndCrossTheBranchCutSmoothly) {
  const std::string csv = testing::TempDir() + "station_interpolation.csv";
  const std::string out = test::RunnerOutput(
      "test/data/urdf/rotating_cantilever.urdf",
      "beams:\n"
      "  blade: {length: 10.0, elements: 10, section: {EA: 2.8e7, GA2: 1.0e7, GA3: 1.0e7, GJ: 1.4e4, EI2: 1.4e4,"
      " EI3: 1.4e4, m: 1.2, m_ii: [1.2e-3, 6.0e-4, 6.0e-4]}}\n"
      "joints:\n"
      "  spin: {drive: {law: rate_ramp, rate: 4.0, duration: 15.0}}\n"
      "solver: {t_end: 30.0, dt: 1.0e-3, gravity: [0, 0, 0]}\n"
      "output: {rate_hz: 100, csv: " + csv + ", beam_stations: {blade: [10.0]}}\n",
      "station_interpolation");
  ASSERT_NE(out.find("finished at t = "), std::string::npos) << out;
  const test::CsvTable table = test::ReadCsv(csv);
  // Centrifugal stretch of the tip: N(s) = m Omega^2 (L^2 - s^2) / 2, u = integral of N / EA = m Omega^2 L^3 / (3 EA).
  const double stretch = kMassPerLength * kOmega * kOmega * kLength * kLength * kLength / (3.0 * kEA);
  // After the ramp (from 18 s) the tip's radius at the steps themselves (rate_hz 0) stays within 1e-6 m of the closed
  // form (its lag vibration's foreshortening, 1.1e-3 rad of lag); the cubic between steps of up to 0.011 s errs by
  // R (Omega h)^4 / 384 = 1e-7 m. The bound is 2e-6 m, 1% of the stretch (the chord erred by up to 2.2e-3 m).
  constexpr double kRadiusTolerance = 2.0e-6;
  // The tip section turns with the hub and its lag slope, 1.5e-3 rad at the steps after the ramp; the bound is
  // 5e-3 rad (linear interpolation across the branch cut was off by up to 3.1 rad).
  constexpr double kTurnTolerance = 5.0e-3;
  int checked = 0;
  for (const std::vector<double>& row : table.rows) {
    if (row.at(table.Column("t")) < 18.0) continue;
    ++checked;
    const double x = kLength + row.at(table.Column("beam.blade.s0.ux")), y = row.at(table.Column("beam.blade.s0.uy"));
    EXPECT_NEAR(std::hypot(x, y) - kLength, stretch, kRadiusTolerance) << "t " << row.at(0);
    const double hub = row.at(table.Column("joint.spin.position"));
    EXPECT_NEAR(Wrapped(row.at(table.Column("beam.blade.s0.rz")) - hub), 0.0, kTurnTolerance) << "t " << row.at(0);
  }
  EXPECT_EQ(checked, 1201);
}

// A free fall on a slide, fixed steps of 0.02 s sampled at 1 kHz: the scheme integrates a constant force exactly
// (q = -g t^2 / 2 at every step end, with its rate), and the cubic through the ends' positions and rates is that
// parabola, so the samples between the steps are exact to round-off (measured 4.4e-16 m; 1e-12 m bounds it with
// room). The chord between the ends fell short by up to g h^2 / 8 = 4.9e-4 m (measured, at every mid-step).
TEST(BeamStationInterpolation, JointSamplesBetweenStepsFollowTheStepsParabola) {
  const std::string csv = testing::TempDir() + "joint_interpolation.csv";
  const std::string out = test::RunnerOutput("test/data/urdf/ball_drop.urdf",
                                             "solver: {t_end: 0.3, adaptive: false, dt: 0.02}\n"
                                             "output: {rate_hz: 1000, csv: " + csv + "}\n",
                                             "joint_interpolation");
  ASSERT_NE(out.find("finished at t = "), std::string::npos) << out;
  const test::CsvTable table = test::ReadCsv(csv);
  constexpr double kGravity = 9.81, kRoundOff = 1.0e-12;  // [m/s^2], [m]
  ASSERT_EQ(table.rows.size(), 301u);
  for (const std::vector<double>& row : table.rows) {
    const double t = row.at(table.Column("t"));
    EXPECT_NEAR(row.at(table.Column("joint.z.position")), -kGravity * t * t / 2.0, kRoundOff) << "t " << t;
  }
}

}  // namespace beam_station_interpolation_test
}  // namespace flexmbd
