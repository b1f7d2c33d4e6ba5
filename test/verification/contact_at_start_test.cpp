// The contact intervals a dynamic run reports (the runner's "stop ...: N contact interval(s)" line) when a contact
// holds at its start: a static analysis (solver.static_first) closed it, so the model's initial state has the stop
// open. The count once started from those initial modes and printed "0 contact interval(s)" for a blade resting on
// its stop in every sample; the contact is one interval from t0, for a rigid stop and an elastic one alike.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "runner_equilibrium.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace contact_at_start_test {

// hbeam.urdf's blade, 1 m of 2 kg/m in four elements, and the start of its hinge's entry.
constexpr const char* kBladeOnAHinge =
    "beams:\n"
    "  blade: {length: 1.0, elements: 4, damping: 1.0e-4, section: {EA: 1.0e8, GA2: 1.0e7, GA3: 1.0e7, GJ: 1.0e3,"
    " EI2: 1.0e3, EI3: 1.0e3, m: 2.0, m_ii: [1.0e-3, 1.0e-5, 1.0e-5]}}\n"
    "joints:\n"
    "  hinge:\n";

TEST(ContactAtStart, BladeRestingOnItsStopAfterAStaticAnalysisHasOneIntervalFromTheStart) {
  // hbeam.urdf: a flexible blade hinged at its root, resting under gravity on a rigid upper stop at 0 (radius
  // 0.1 m), at rest throughout: the stop force 98.1 N never lets go.
  const std::string yaml = std::string(kBladeOnAHinge) +
      "    backlash: {upper: 0.0, radius_upper: 0.1}\n"
      "solver: {t_end: 0.5, static_first: true}\n";
  const std::string out = test::RunnerOutput("test/data/urdf/hbeam.urdf", yaml, "contact_at_start");
  EXPECT_NE(out.find("stop hinge upper: 1 contact interval(s) [0, 0.5] s"), std::string::npos) << out;
}

TEST(ContactAtStart, BladeRestingOnAnElasticStopAfterAStaticAnalysisHasOneIntervalFromTheStart) {
  // The blade above on a Hertz stop (k 1e6 N/m^1.5), started 0.01 rad off it: the equilibrium presses it with 98.1 N
  // (an approach of 2.1e-3 m), which never lets go. Its interval once opened at the end of the first step ([0.01,
  // 0.5] s), as only a step committed an elastic contact.
  const std::string yaml = std::string(kBladeOnAHinge) +
      "    initial: {position: -0.01}\n"
      "    backlash: {upper: 0.0, radius_upper: 0.1, stop: {type: elastic, law: hertz, stiffness: 1.0e6,"
      " restitution: 0.7}}\n"
      "solver: {t_end: 0.5, static_first: true}\n";
  const std::string out = test::RunnerOutput("test/data/urdf/hbeam.urdf", yaml, "elastic_contact_at_start");
  EXPECT_NE(out.find("stop hinge upper: 1 contact interval(s) [0, 0.5] s"), std::string::npos) << out;
}

// stick_slip.urdf's 1 kg slider pressed by a spring (k 100 N/m, rest 0.1 m) onto a stop at 0.05 m, where it starts at
// rest: a contact that holds at t = 0 without a static analysis, with the force k (rest - stop) = 5 N.
std::string PressedSlider(const std::string& stop) {
  return "joints:\n  slider:\n    spring: {k: 100.0, rest: 0.1}\n    initial: {position: 0.05}\n"
         "    backlash: {upper: 0.05" + stop + "}\n";
}

TEST(ContactAtStart, SliderPressedOntoARigidStopShowsTheContactForceInEveryRowFromTheFirst) {
  // Nothing moves, so every row, the first included, has the slider in contact with the force 5 N (torque -5 N on
  // the slide) to round-off, and the effort (spring plus stop) zero. The first row read the stop open, force 0, while
  // the effort already held the stop's -5 N and the runner reported the contact from t = 0 (explore6).
  constexpr double kRoundOff = 1.0e-12;
  test::CsvTable csv;
  test::EquilibriumRow("test/data/urdf/stick_slip.urdf", PressedSlider("") + "solver: {t_end: 0.1}\n",
                       "pressed_rigid", &csv);
  ASSERT_GT(csv.rows.size(), 2u);
  for (const std::vector<double>& row : csv.rows) {
    EXPECT_EQ(row[csv.Column("stop.slider.upper.in_contact")], 1.0) << "t = " << row[0];
    EXPECT_NEAR(row[csv.Column("stop.slider.upper.force")], 5.0, 5.0 * kRoundOff) << "t = " << row[0];
    EXPECT_NEAR(row[csv.Column("stop.slider.upper.torque")], -5.0, 5.0 * kRoundOff) << "t = " << row[0];
    EXPECT_NEAR(row[csv.Column("joint.slider.effort")], 0.0, 5.0 * kRoundOff) << "t = " << row[0];
  }
}

TEST(ContactAtStart, ElasticStopTouchedAtRestNeverShowsAPullingForce) {
  // The same slider on a linear elastic stop (1e5 N/m, lossless) touching it at t = 0: the approach is 0 there, so the
  // law's force is 0, and a stop never pulls: no row has a negative force. The first row once showed -2.5e-5 N, the
  // extrapolation to a step of length 0 (docs/config.md, "Samples") of forces that grow as h^2 from rest.
  test::CsvTable csv;
  test::EquilibriumRow("test/data/urdf/stick_slip.urdf",
                       PressedSlider(", stop: {type: elastic, law: linear, stiffness: 1.0e5, restitution: 1.0}") +
                           "solver: {t_end: 0.02}\n",
                       "pressed_elastic", &csv);
  ASSERT_GT(csv.rows.size(), 2u);
  EXPECT_EQ(csv.rows.front()[csv.Column("stop.slider.upper.force")], 0.0);
  for (const std::vector<double>& row : csv.rows) {
    EXPECT_GE(row[csv.Column("stop.slider.upper.force")], 0.0) << "t = " << row[0];
  }
}

TEST(ContactAtStart, ElasticStopTouchedAtRestUnderAPreloadOscillatesAsAMassOnASpring) {
  // The slider pressed by 1 N (spring rest 0.06 m) onto a lossless linear stop of 1e5 N/m that it touches at rest:
  // from t = 0 it is a mass on the two springs, the approach a(t) = a* (1 - cos w t), a* = F / (k_s + k), w =
  // sqrt((k_s + k) / m): it swings to 2 a* = 2.0e-5 m at T / 2, T = 19.86 ms, and back to the stop, 5 times in 0.1 s.
  // The energy-decaying scheme's own losses on a linear oscillator, measured at fixed steps (omega h 0.22 to 0.63):
  // 0.124 (omega h)^2 of its energy per period, and the period (omega h)^2 / 12 long. At the steps the run takes (up
  // to 2.5e-3 s, omega h 0.79) that allows 2% of the swing's height (half a period's loss: 3.9% of the energy),
  // 2.6% of T on the first swing's instant (half the lengthening), and 39% of the energy over the 5 periods.
  // Measured: -0.2%, 0.3% of T, 15%, as when the same contact is entered from a gap of 1e-9 m during the run (15%).
  // Before the trials took their steps without the scheme's dissipation, that dissipation hid the contact from the
  // trials' error estimate (T12) and the run began with three steps of 0.01 s (two per period): the first swing went
  // to +4% at 0.0149 s (25% of T late), and 62% of the energy was lost.
  constexpr double kMass = 1.0, kSpring = 100.0, kStop = 1.0e5, kPreload = 1.0, kPi = 3.14159265358979323846;
  constexpr double kLargestStep = 2.5e-3, kHeight = 0.02, kInstant = 0.026, kLoss = 0.39;
  const std::string csv_path = testing::TempDir() + "preloaded_elastic.csv";
  test::RunnerOutput("test/data/urdf/stick_slip.urdf",
                     "joints:\n  slider:\n    spring: {k: 100.0, rest: 0.06}\n    initial: {position: 0.05}\n"
                     "    backlash: {upper: 0.05,\n"
                     "               stop: {type: elastic, law: linear, stiffness: 1.0e5, restitution: 1.0}}\n"
                     "solver: {t_end: 0.1}\noutput: {rate_hz: 20000, csv: " + csv_path + "}\n",
                     "preloaded_elastic");
  const test::CsvTable csv = test::ReadCsv(csv_path);
  ASSERT_GT(csv.rows.size(), 1000u);
  const double swing = 2.0 * kPreload / (kStop + kSpring), omega = std::sqrt((kStop + kSpring) / kMass);
  const double period = 2.0 * kPi / omega, energy = kPreload * kPreload / (2.0 * (kStop + kSpring));
  double peak = 0, peak_time = 0, largest_step = 0;
  for (const std::vector<double>& row : csv.rows) {
    largest_step = std::max(largest_step, row[csv.Column("solver.dt")]);
    const double approach = row[csv.Column("joint.slider.position")] - 0.05;
    if (row[0] <= period && approach > peak) {
      peak = approach;
      peak_time = row[0];
    }
  }
  EXPECT_LE(largest_step, kLargestStep);
  EXPECT_NEAR(peak / swing, 1.0, kHeight);
  EXPECT_NEAR(peak_time, 0.5 * period, kInstant * period);
  EXPECT_LE(csv.rows.back()[csv.Column("energy.numerical_dissipation")], kLoss * energy);
}

}  // namespace contact_at_start_test
}  // namespace flexmbd
