// The fuzzer's inputs (harness/input_generator.hpp): reproducible from (seed, index), and mutated.

#include <gtest/gtest.h>

#include "harness/input_generator.hpp"

namespace flexmbd {
namespace fuzz {
namespace input_generator_test {

const std::string kRoot = FLEXMBD_SOURCE_DIR;

std::vector<SeedCase> Seeds() { return ReadSeedCorpus(kRoot, kRoot + "/test/fuzz/seeds.txt"); }

TEST(InputGenerator, SameSeedAndIndexGiveTheSameInput) {
  const InputGenerator first(Seeds()), second(Seeds());
  for (uint64_t index : {0u, 1u, 77u, 12345u}) {
    const FuzzInput a = first.Make(7, index), b = second.Make(7, index);
    EXPECT_EQ(a.urdf, b.urdf) << index;
    EXPECT_EQ(a.yaml, b.yaml) << index;
    EXPECT_EQ(a.channel, b.channel) << index;
  }
}

TEST(InputGenerator, InputsDifferFromEverySeed) {
  const std::vector<SeedCase> seeds = Seeds();
  const InputGenerator generator(seeds);
  int unchanged = 0;
  constexpr int kInputs = 200;
  for (int index = 0; index < kInputs; ++index) {
    const FuzzInput input = generator.Make(1, static_cast<uint64_t>(index));
    for (const SeedCase& seed : seeds) {
      if (input.urdf == seed.urdf && input.yaml == seed.yaml) ++unchanged;
    }
  }
  // a mutation can be a no-op (a value replaced by itself, an empty list left empty); a few percent at most
  EXPECT_LT(unchanged, kInputs / 20);
}

}  // namespace input_generator_test
}  // namespace fuzz
}  // namespace flexmbd
