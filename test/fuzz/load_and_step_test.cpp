// The fuzzer's in-process target (harness/load_and_step.hpp) on the seed cases and on known bad input.

#include <gtest/gtest.h>

#include <string>

#include "harness/isolated_run.hpp"
#include "harness/load_and_step.hpp"
#include "harness/seed_corpus.hpp"

namespace flexmbd {
namespace fuzz {
namespace load_and_step_test {

const std::string kRoot = FLEXMBD_SOURCE_DIR;

std::vector<SeedCase> Seeds() { return ReadSeedCorpus(kRoot, kRoot + "/test/fuzz/seeds.txt"); }

std::string PendulumUrdf() {
  for (const SeedCase& seed : Seeds()) {
    if (seed.name == "test/data/urdf/pendulum.urdf + test/data/yaml/pendulum.yaml") return seed.urdf;
  }
  ADD_FAILURE() << "test/fuzz/seeds.txt lost the pendulum";
  return "";
}

TEST(LoadAndStep, SeedCasesCompleteOrFailWithTheirOwnErrors) {
  for (const SeedCase& seed : Seeds()) {
    const TargetResult result = LoadAndStep(FuzzInput{seed.urdf, seed.yaml, Channel::kFiles});
    const bool invalid_seed = seed.name.find("invalid") != std::string::npos;
    EXPECT_EQ(result.outcome, invalid_seed ? Outcome::kConfigError : Outcome::kCompleted)
        << seed.name << ": " << result.message;
  }
}

TEST(LoadAndStep, BadValueIsAConfigErrorNamingTheYamlFile) {
  const TargetResult result = LoadAndStep(FuzzInput{PendulumUrdf(), "solver: {dt: .nan}\n", Channel::kFiles});
  EXPECT_EQ(result.outcome, Outcome::kConfigError);
  EXPECT_NE(result.message.find("fuzz_case.yaml: solver.dt"), std::string::npos) << result.message;
}

TEST(LoadAndStep, ParameterChannelNamesTheNamespace) {
  const TargetResult result = LoadAndStep(FuzzInput{PendulumUrdf(), "solver: {dt: -1}\n", Channel::kParamTree});
  EXPECT_EQ(result.outcome, Outcome::kConfigError);
  EXPECT_NE(result.message.find("/flexmbd_node"), std::string::npos) << result.message;
}

std::string SeedUrdf(const std::string& name) {
  for (const SeedCase& seed : Seeds()) {
    if (seed.name.rfind(name, 0) == 0) return seed.urdf;
  }
  ADD_FAILURE() << "test/fuzz/seeds.txt lost " << name;
  return "";
}

TEST(LoadAndStep, LargerModelsGetLongerTimeLimits) {
  EXPECT_EQ(TimeLimitFactor(12), 1u);
  EXPECT_EQ(TimeLimitFactor(kUnknownsPerTimeLimit - 1), 1u);
  EXPECT_EQ(TimeLimitFactor(36 * kUnknownsPerTimeLimit), 36u);
  // In the child, the limit left after the run: a beam of 1,000 cubic elements (3,001 nodes, 18,006 unknowns with
  // the clamp) gets three times the 100 s given.
  const std::string beam = "beams: {arm: {length: 1.0, elements: 1000, order: 3, section: {EA: 1.0e7, GA2: 4.0e6, "
                           "GA3: 4.0e6, GJ: 50.0, EI2: 80.0, EI3: 100.0, m: 2.5, m_ii: [0.002, 0.001, 0.001]}}}\n"
                           "solver: {t_end: 1.0e-6, dt: 1.0e-6}\n";
  IsolationLimits limits;
  limits.seconds = 100;
  const IsolatedResult isolated = RunIsolated(
      [&] {
        const TargetResult run =
            LoadAndStep(FuzzInput{SeedUrdf("test/data/urdf/beam_arm.urdf"), beam, Channel::kFiles});
        return TargetResult{run.outcome, run.message + "|" + std::to_string(CpuSecondsLeft())};
      },
      limits);
  ASSERT_EQ(isolated.termination, Termination::kReturned);
  EXPECT_EQ(isolated.result.outcome, Outcome::kCompleted) << isolated.result.message;
  const double left = std::stod(isolated.result.message.substr(isolated.result.message.find('|') + 1));
  EXPECT_GT(left, 200.0);
}

TEST(LoadAndStep, HugeEndTimeRunsOnlyTheFirstSteps) {
  // with no file and a sample every step the end time is not bounded, so this loads; the target must end at once
  const TargetResult result =
      LoadAndStep(FuzzInput{PendulumUrdf(), "solver: {t_end: 1.0e300}\noutput: {rate_hz: 0}\n", Channel::kFiles});
  EXPECT_EQ(result.outcome, Outcome::kCompleted) << result.message;
}

}  // namespace load_and_step_test
}  // namespace fuzz
}  // namespace flexmbd
