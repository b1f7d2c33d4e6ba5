// The fuzzer's in-process target (harness/load_and_step.hpp) on the seed cases and on known bad input.

#include <gtest/gtest.h>

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

TEST(LoadAndStep, HugeEndTimeRunsOnlyTheFirstSteps) {
  // with no file and a sample every step the end time is not bounded, so this loads; the target must end at once
  const TargetResult result =
      LoadAndStep(FuzzInput{PendulumUrdf(), "solver: {t_end: 1.0e300}\noutput: {rate_hz: 0}\n", Channel::kFiles});
  EXPECT_EQ(result.outcome, Outcome::kCompleted) << result.message;
}

}  // namespace load_and_step_test
}  // namespace fuzz
}  // namespace flexmbd
