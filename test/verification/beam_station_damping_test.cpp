// The structural damping part of the section forces at beam stations (docs/theory.md, "Station outputs", (B7)),
// through the runner, its YAML and its CSV.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../integration/helpers/csv_table.hpp"
#include "beam_cases.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace beam_station_damping_test {

// A 1 m blade of m = 5 kg/m on test/data/urdf/spinning_hub.urdf, with structural damping mu = 0.01 s, spun at
// 20 rad/s from t = 0 by its hub's drive; `solver` is the solver block, `rate_hz` the output rate.
std::string DampedBlade(const std::string& solver, const std::string& rate_hz, const std::string& csv) {
  return std::string(
             "beams:\n"
         "  blade:\n"
         "    length: 1.0\n"
         "    elements: 4\n"
         "    order: 3\n"
         "    damping: 0.01\n"
         "    section: {EA: 1.0e7, GA2: 4.0e6, GA3: 4.0e6, GJ: 50.0, EI2: 80.0, EI3: 100.0, m: 5.0,\n"
         "              m_ii: [0.002, 0.001, 0.001]}\n"
         "joints: {spin: {drive: {law: linear_ramp, value: 20.0, duration: 1.0}}}\n") +
         solver +
         "output: {rate_hz: " + rate_hz + ", csv: " + csv + ", beam_stations: {blade: [0.0, 0.5]}}\n";
}

TEST(BeamStationDamping, SteadySpinGivesTheCentrifugalTensionAndNoLagShear) {
  // The hub turns at Omega = 20 rad/s from t = 0 (a drive), the blade starting straight and unstretched. Steady
  // spin: the tension at s is the centrifugal load outboard of it, m Omega^2 (L^2 - s^2) / 2 (1000 N at the root,
  // 750 N at mid-span), and no shear or moment acts (a rigid rotation strains nothing, and its damping forces are
  // zero). The axial transient is overdamped (mu omega_axial / 2 = 16) and decays as exp(-t / mu): gone (e^-20)
  // by 0.2 s. The tension of the model is not the closed form's: its lumped node masses load the blade in steps
  // that the 4 cubic elements' Gauss-point recovery smooths, 0.55% at the root and 0.71% at mid-span (0.18% and
  // 0.22% with 8 elements; steps eight times shorter change it by 6e-4), so 1e-2. The shears and moments were
  // mu GA times the spurious strain rate of the end velocities, up to 1062 N at mid-span (issue: 234 N at the
  // root); left is the lag vibration the axial transient's Coriolis forces start, 0.43 N at most: 1 N bounds it.
  constexpr double kOmega = 20.0, kMass = 5.0, kLength = 1.0, kTension = 1.0e-2, kShear = 1.0;
  const std::string csv = testing::TempDir() + "spinning_damped_blade.csv";
  test::RunnerOutput("test/data/urdf/spinning_hub.urdf",
                     DampedBlade("solver: {t_end: 0.6, gravity: [0.0, 0.0, 0.0]}\n", "200", csv),
                     "spinning_damped_blade");
  const test::CsvTable table = test::ReadCsv(csv);
  int checked = 0;
  double worst_tension = 0, worst_shear = 0;
  for (const std::vector<double>& row : table.rows) {
    const double t = row[table.Column("t")];
    if (t < 0.2) continue;
    for (const auto& [station, s] : {std::make_pair("s0", 0.0), std::make_pair("s1", 0.5)}) {
      const std::string column = std::string("beam.blade.") + station + ".";
      const double tension = kMass * kOmega * kOmega * (kLength * kLength - s * s) / 2;
      const double N = row[table.Column(column + "N")];
      EXPECT_NEAR(N / tension, 1.0, kTension) << "t " << t << ", s " << s;
      worst_tension = std::max(worst_tension, std::abs(N / tension - 1));
      for (const char* other : {"V2", "V3", "T", "M2", "M3"}) {
        const double value = row[table.Column(column + other)];
        EXPECT_LT(std::abs(value), kShear) << other << ", t " << t << ", s " << s;
        worst_shear = std::max(worst_shear, std::abs(value));
      }
    }
    ++checked;
  }
  EXPECT_GE(checked, 80);  // 0.2 to 0.6 s at 200 Hz
  RecordProperty("tension_error", test::Figure(worst_tension));
  RecordProperty("largest_shear_or_moment_N_or_Nm", test::Figure(worst_shear));
}

TEST(BeamStationDamping, LastSampleOfARunCutShortStaysWithTheOthers) {
  // The blade above on fixed 2 ms steps to t_end = 0.6002 s, every step written. The run once ended with a step of
  // 0.2 ms, whose forces carry the alternating mode of its start velocities divided by its size: the last sample's
  // hub effort jumped by 0.088 N m and the root's lag shear by 1.07 N from the sample before, where the steps before
  // change them by less than 1e-3 N m and 0.01 N. The last steps now share the time left (docs/theory.md (T12),
  // "Last steps"): here three of 1.4 ms. Any change of step size moves these forces, the effort by 0.098 N m times
  // the change over the step (last steps cut to 0.1, 0.4, 0.7 and 0.9 of it gave 0.088, 0.051, 0.027 and 9.6e-3 N m;
  // the shear 1.07, 0.44, 0.20 and 0.067 N): a change of 0.3 of the step moves them by a third of the old cut's
  // change of 0.9 or less, and a third of the old jumps bounds every sample of the last steps.
  constexpr double kEffortJump = 0.088 / 3, kShearJump = 1.07 / 3, kStep = 2.0e-3;
  constexpr int kLast = 3;  // steps that share the time left, at 2/3 to 1.01 of kStep
  const std::string csv = testing::TempDir() + "spinning_damped_blade_cut.csv";
  test::RunnerOutput(
      "test/data/urdf/spinning_hub.urdf",
      DampedBlade("solver: {t_end: 0.6002, adaptive: false, dt: 2.0e-3, gravity: [0.0, 0.0, 0.0]}\n", "0", csv),
      "spinning_damped_blade_cut");
  const test::CsvTable table = test::ReadCsv(csv);
  ASSERT_GE(table.rows.size(), static_cast<size_t>(kLast + 2));
  EXPECT_NEAR(table.rows.back()[table.Column("t")], 0.6002, 1e-12);
  const size_t dt = table.Column("solver.dt");
  for (const auto& [column, bound] : {std::make_pair("joint.spin.effort", kEffortJump),
                                      std::make_pair("beam.blade.s0.V2", kShearJump)}) {
    double worst = 0;
    for (size_t k = table.rows.size() - kLast; k < table.rows.size(); ++k) {
      const std::vector<double>&now = table.rows[k], &before = table.rows[k - 1];
      EXPECT_LE(now[dt], kStep * 1.01);
      EXPECT_GE(now[dt], kStep * 2 / 3);
      worst = std::max(worst, std::abs(now[table.Column(column)] - before[table.Column(column)]));
    }
    EXPECT_LT(worst, bound) << column;
    RecordProperty(std::string("largest_jump_of_the_last_steps_") + column, test::Figure(worst));
  }
}

TEST(BeamStationDamping, VibratingBeamCarriesMuEITimesItsCurvatureRate) {
  // test/data/urdf/beam_arm.urdf: a clamped 1 m arm (EI3 = 100 N m^2, 2 cubic elements, a 2 kg tip mass on a
  // hinge) shaken across by a 20 N tip force at 1 Hz, with mu = 0.02 s (first mode ~10.7 rad/s, zeta 0.1). The root
  // moment is EI3 (k3 + mu k3_dot) (B7): its damping part, M3 - EI3 k3 from the CSV's own columns, against mu EI3
  // times the curvature rate of the samples (central differences over the fixed 1 ms steps, 1000 samples/s). The
  // damping part reads the rate over the step that ends at the sample, which lags it by h / 2: omega h / 2 = 5e-3
  // relative for the first mode, the fastest that lasts (higher ones are overdamped); 1e-2 of the RMS bounds it.
  const std::string csv = testing::TempDir() + "shaken_damped_arm.csv";
  test::RunnerOutput("test/data/urdf/beam_arm.urdf",
                     "beams:\n"
                     "  arm:\n"
                     "    length: 1.0\n"
                     "    elements: 2\n"
                     "    order: 3\n"
                     "    damping: 0.02\n"
                     "    section: {EA: 1.0e7, GA2: 4.0e6, GA3: 4.0e6, GJ: 50.0, EI2: 80.0, EI3: 100.0, m: 2.5,\n"
                     "              m_ii: [0.002, 0.001, 0.001]}\n"
                     "loads: [{body: arm, force: [0.0, 20.0, 0.0], point: [1.0, 0.0, 0.0],\n"
                     "         scale: {law: sine, amplitude: 1.0, frequency: 1.0}}]\n"
                     "solver: {t_end: 1.0, dt: 1.0e-3, adaptive: false, gravity: [0.0, 0.0, 0.0]}\n"
                     "output: {rate_hz: 1000, csv: " + csv + ", beam_stations: {arm: [0.0]}}\n",
                     "shaken_damped_arm");
  const test::CsvTable table = test::ReadCsv(csv);
  constexpr double kEI = 100.0, kMu = 0.02, kRelative = 1.0e-2;
  const size_t t = table.Column("t"), k3 = table.Column("beam.arm.s0.k3"), M3 = table.Column("beam.arm.s0.M3");
  double error = 0, reference = 0;
  for (size_t n = 1; n + 1 < table.rows.size(); ++n) {
    const std::vector<double>&before = table.rows[n - 1], &now = table.rows[n], &after = table.rows[n + 1];
    if (now[t] < 0.1) continue;
    const double rate = (after[k3] - before[k3]) / (after[t] - before[t]);
    const double damping = now[M3] - kEI * now[k3];
    error += std::pow(damping - kMu * kEI * rate, 2);
    reference += std::pow(kMu * kEI * rate, 2);
  }
  ASSERT_GT(reference, 0.0);
  EXPECT_LT(std::sqrt(error / reference), kRelative);
  RecordProperty("damping_part_rms_error", test::Figure(std::sqrt(error / reference)));
}

}  // namespace beam_station_damping_test
}  // namespace flexmbd
