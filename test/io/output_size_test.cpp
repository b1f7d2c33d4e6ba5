// The bound on what a run writes (include/flexmbd/model/output_size.hpp, docs/config.md "output"):
// samples x values per sample above kMaxOutputValues is a ConfigError naming the fields, unless
// output.allow_large_output is set. Reference: the CSV columns of docs/config.md.

#include <gtest/gtest.h>

#include "flexmbd/model/output_size.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace output_size_test {
using test::LoadDataUrdf;

Model Pendulum(const std::string& yaml) { return BuildModel(LoadDataUrdf("pendulum.urdf", yaml, "pendulum.yaml")); }

// pendulum.urdf: one revolute joint: t, 3 variable columns, 6 reaction columns, 8 energy and step columns.
constexpr long kPendulumValuesPerSample = 18;

TEST(OutputSize, ValuesPerSampleCountTheCsvColumns) {
  EXPECT_EQ(OutputValuesPerSample(Pendulum("")), kPendulumValuesPerSample);
}

TEST(OutputSize, BeamStationsAddEighteenValuesEach) {
  const std::string yaml = test::ReadDataText("yaml/beam_arm.yaml") + "output: {beam_stations: {arm: [0.0, 1.0]}}\n";
  const Model with = BuildModel(LoadDataUrdf("beam_arm.urdf", yaml, "beam_arm.yaml"));
  const Model without =
      BuildModel(LoadDataUrdf("beam_arm.urdf", test::ReadDataText("yaml/beam_arm.yaml"), "beam_arm.yaml"));
  EXPECT_EQ(OutputValuesPerSample(with) - OutputValuesPerSample(without), 2 * 18);
}

TEST(OutputSize, HugeRateTimesEndTimeIsRejectedNamingTheFields) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {t_end: 1.0e300}\noutput: {rate_hz: 1.0e6, csv: run.csv}"),
                      "pendulum.urdf + pendulum.yaml: output.rate_hz 1e+06 Hz and solver.t_end 1e+300 s give 1e+306 "
                      "samples of 18 values");
  EXPECT_CONFIG_ERROR(Pendulum("solver: {t_end: 1.0e300}\noutput: {rate_hz: 1.0e6, csv: run.csv}"),
                      "more than 4e+07 (about 1 GB of CSV); expected a lower rate_hz, a shorter t_end, or "
                      "output.allow_large_output: true");
}

TEST(OutputSize, JustAboveTheBoundIsRejectedAndJustBelowLoads) {
  // 18 values per sample: 40,000,000 / 18 = 2,222,222.2 samples; rate 1 Hz gives t_end + 1 samples
  EXPECT_CONFIG_ERROR(Pendulum("solver: {t_end: 2222222}\noutput: {rate_hz: 1, bag: run.bag}"), "more than 4e+07");
  EXPECT_NO_THROW(Pendulum("solver: {t_end: 2222220}\noutput: {rate_hz: 1, bag: run.bag}"));
}

TEST(OutputSize, EveryStepRateCountsStepsOfDtMax) {
  EXPECT_CONFIG_ERROR(Pendulum("solver: {t_end: 1.0e6, dt: 1.0e-3, dt_max: 1.0e-3}\noutput: {rate_hz: 0, csv: a.csv}"),
                      "(one per step, at least t_end / dt_max)");
}

TEST(OutputSize, FixedStepsCountStepsOfDt) {
  EXPECT_CONFIG_ERROR(
      Pendulum("solver: {t_end: 1.0e5, dt: 1.0e-3, adaptive: false}\noutput: {rate_hz: 0, csv: a.csv}"),
      "(one per step, at least t_end / dt)");
}

TEST(OutputSize, BeamStationsAreNamedWhenTheyCount) {
  const std::string yaml = "beams: {arm: {length: 1.0, elements: 2, order: 3, section: {EA: 1.0e7, GA2: 4.0e6, "
                           "GA3: 4.0e6, GJ: 50.0, EI2: 80.0, EI3: 100.0, m: 2.5, m_ii: [0.002, 0.001, 0.001]}}}\n"
                           "solver: {t_end: 1.0e5}\noutput: {rate_hz: 100, csv: a.csv, beam_stations: {arm: [0.5]}}\n";
  EXPECT_CONFIG_ERROR(BuildModel(LoadDataUrdf("beam_arm.urdf", yaml, "beam_arm.yaml")),
                      "(18 of them from output.beam_stations)");
}

TEST(OutputSize, OptInAllowsLargeOutput) {
  EXPECT_NO_THROW(
      Pendulum("solver: {t_end: 1.0e300}\noutput: {rate_hz: 1.0e6, csv: run.csv, allow_large_output: true}"));
}

TEST(OutputSize, RunWithoutCsvOrBagIsBoundedInSamples) {
  // fuzz finding (test/fuzz): rate_hz 1e18 with no file interpolated samples for ever
  EXPECT_CONFIG_ERROR(Pendulum("solver: {t_end: 1.0e300}\noutput: {rate_hz: 1.0e6}"),
                      "pendulum.urdf + pendulum.yaml: output.rate_hz 1e+06 Hz and solver.t_end 1e+300 s give 1e+306 "
                      "samples, more than 4e+07 (each is interpolated and passed on, with or without an output file)");
  EXPECT_NO_THROW(Pendulum("solver: {t_end: 3.9e7}\noutput: {rate_hz: 1}"));
  EXPECT_NO_THROW(Pendulum("solver: {t_end: 1.0e300}\noutput: {rate_hz: 1.0e6, allow_large_output: true}"));
}

TEST(OutputSize, RunWithoutCsvOrBagAtEveryStepIsNotBounded) {
  EXPECT_NO_THROW(Pendulum("solver: {t_end: 1.0e300}\noutput: {rate_hz: 0}"));
}

TEST(OutputSize, StaticAnalysisWritesOneSample) {
  EXPECT_NO_THROW(Pendulum("solver: {analysis: static, t_end: 1.0e300}\noutput: {rate_hz: 1.0e6, csv: run.csv}"));
}

TEST(OutputSize, OptInMustBeABoolean) {
  EXPECT_CONFIG_ERROR(Pendulum("output: {allow_large_output: 3}"), "pendulum.yaml: output.allow_large_output: ");
}

}  // namespace output_size_test
}  // namespace flexmbd
