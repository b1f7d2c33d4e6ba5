// CI's fuzzing batch (test/fuzz/README.md): a fixed seed, so a failure is a reproducible finding, written
// as a reproducer pair whose path the failure prints.

#include <gtest/gtest.h>

#include <cstdlib>

#include "harness/campaign.hpp"

namespace flexmbd {
namespace fuzz {
namespace fixed_seed_batch_test {

const std::string kRoot = FLEXMBD_SOURCE_DIR;

// Inputs of the batch: about 15 s on the 2-core development machine (bench/README.md, fuzz_config).
constexpr uint64_t kBatchInputs = 400;
constexpr uint64_t kBatchSeed = 1;

TEST(FuzzBatch, FixedSeedBatchHasNoFindings) {
  CampaignOptions options;
  options.seed = kBatchSeed;
  options.inputs = kBatchInputs;
  options.out_dir = ::testing::TempDir() + "flexmbd_fuzz_findings";
  options.limits.seconds = 10;  // a hang never ends; the slowest seed input takes well under 1 s
  const CampaignCounts counts = RunCampaign(InputGenerator(ReadSeedCorpus(kRoot, kRoot + "/test/fuzz/seeds.txt")),
                                            options);
  std::string reproducers;
  for (const std::string& path : counts.reproducers) reproducers += "\n  " + path;
  EXPECT_EQ(counts.findings(), 0u) << counts.crashes << " crashes, " << counts.hangs << " hangs, "
                                   << counts.wrong_exceptions << " wrong exceptions, " << counts.bad_messages
                                   << " bad messages; reproducers:" << reproducers;
  EXPECT_EQ(counts.inputs, kBatchInputs);
  // the mutations must leave inputs on both sides of the loader's checks, or the batch tests nothing
  EXPECT_GT(counts.completed, kBatchInputs / 20);
  EXPECT_GT(counts.config_errors, kBatchInputs / 5);
}

}  // namespace fixed_seed_batch_test
}  // namespace fuzz
}  // namespace flexmbd
