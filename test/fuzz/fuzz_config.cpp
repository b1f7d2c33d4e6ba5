// Long fuzzing runs of the loader and the first solver steps (test/fuzz/README.md, bench/README.md).
//   fuzz_config [--inputs N] [--seed S] [--out DIR] [--seconds T] [--time-limit S] [--source DIR]
//   fuzz_config --replay URDF YAML [--param-tree]
//   fuzz_config --make K [--seed S] [--out DIR] [--source DIR]
// A campaign prints a progress line every 10,000 inputs and a summary: inputs, inputs per second, outcomes
// and findings; it exits 1 if it found anything. --replay runs one reproducer in this process (no fork, the
// loader's logs shown) and prints its outcome and verdict. --make writes input K of seed S as DIR/input_S_K.urdf,
// .yaml and .txt without running it: a campaign writes only the first findings of each kind, and any input can
// be made again from its seed, its index and the same seed cases.

#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "flexmbd/io/text_file.hpp"
#include "harness/campaign.hpp"
#include "harness/verdict.hpp"

namespace {

using flexmbd::fuzz::CampaignCounts;

constexpr char kUsage[] =
    "usage: fuzz_config [--inputs N] [--seed S] [--out DIR] [--seconds T] [--time-limit S] [--source DIR]\n"
    "       fuzz_config --replay URDF YAML [--param-tree]\n"
    "       fuzz_config --make K [--seed S] [--out DIR] [--source DIR]\n";

// Without sanitizers a runaway allocation is bounded so it ends as std::bad_alloc (a finding), not as the
// machine's memory; AddressSanitizer reserves terabytes of address space and needs no limit.
#if defined(__SANITIZE_ADDRESS__)
constexpr unsigned long kMemoryMib = 0;
#else
constexpr unsigned long kMemoryMib = 4096;
#endif

int Replay(const std::string& urdf, const std::string& yaml, bool param_tree) {
  using namespace flexmbd::fuzz;
  const FuzzInput input{flexmbd::ReadTextFile(urdf, "URDF file"), flexmbd::ReadTextFile(yaml, "YAML file"),
                        param_tree ? Channel::kParamTree : Channel::kFiles};
  IsolatedResult isolated;
  isolated.result = LoadAndStep(input);
  const char* outcomes[] = {"completed", "ConfigError", "SolverError", "other exception"};
  std::printf("outcome: %s%s%s\n", outcomes[static_cast<int>(isolated.result.outcome)],
              isolated.result.message.empty() ? "" : ": ", isolated.result.message.c_str());
  const Verdict verdict = Judge(isolated);
  std::printf("verdict: %s%s%s\n", FindingName(verdict.finding), verdict.detail.empty() ? "" : ": ",
              verdict.detail.c_str());
  return verdict.finding == Finding::kNone ? 0 : 1;
}

void PrintCounts(const CampaignCounts& counts, double seconds) {
  std::printf("fuzz_config: %llu inputs in %.1f s (%.0f inputs/s): %llu completed, %llu ConfigError, "
              "%llu SolverError; findings: %llu crashes, %llu hangs, %llu wrong exceptions, %llu bad messages\n",
              static_cast<unsigned long long>(counts.inputs), seconds, counts.inputs / seconds,
              static_cast<unsigned long long>(counts.completed), static_cast<unsigned long long>(counts.config_errors),
              static_cast<unsigned long long>(counts.solver_errors), static_cast<unsigned long long>(counts.crashes),
              static_cast<unsigned long long>(counts.hangs), static_cast<unsigned long long>(counts.wrong_exceptions),
              static_cast<unsigned long long>(counts.bad_messages));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace flexmbd::fuzz;
  CampaignOptions options;
  options.inputs = 1000000;
  options.out_dir = "fuzz_findings";
  options.limits.memory_mib = kMemoryMib;
  std::string source = FLEXMBD_SOURCE_DIR;
  bool make_one = false;
  uint64_t make_index = 0;
  for (int k = 1; k < argc; ++k) {
    const std::string flag = argv[k];
    if (flag == "--replay" && k + 2 < argc) {
      return Replay(argv[k + 1], argv[k + 2], k + 3 < argc && std::string(argv[k + 3]) == "--param-tree");
    }
    if (k + 1 >= argc) {
      std::fputs(kUsage, stderr);
      return 2;
    }
    const std::string value = argv[++k];
    if (flag == "--inputs") options.inputs = std::strtoull(value.c_str(), nullptr, 10);
    else if (flag == "--seed") options.seed = std::strtoull(value.c_str(), nullptr, 10);
    else if (flag == "--out") options.out_dir = value;
    else if (flag == "--seconds") options.max_seconds = std::atof(value.c_str());
    else if (flag == "--time-limit") options.limits.seconds = static_cast<unsigned>(std::atoi(value.c_str()));
    else if (flag == "--source") source = value;
    else if (flag == "--make") {
      make_one = true;
      make_index = std::strtoull(value.c_str(), nullptr, 10);
    }
    else {
      std::fputs(kUsage, stderr);
      return 2;
    }
  }
  const InputGenerator generator(ReadSeedCorpus(source, source + "/test/fuzz/seeds.txt"));
  if (make_one) {
    mkdir(options.out_dir.c_str(), 0755);
    const std::string stem =
        options.out_dir + "/input_" + std::to_string(options.seed) + "_" + std::to_string(make_index);
    const FuzzInput input = generator.Make(options.seed, make_index);
    try {
      WriteInputFiles(stem, input, DescribeInput(options.seed, make_index, input, stem));
    } catch (const std::runtime_error& error) {
      std::fprintf(stderr, "%s\n", error.what());
      return 1;
    }
    std::printf("wrote %s.urdf, .yaml and .txt\n", stem.c_str());
    return 0;
  }
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const CampaignCounts counts =
      RunCampaign(generator, options, Progress{10000, [&](const CampaignCounts& c) { PrintCounts(c, elapsed()); }});
  PrintCounts(counts, elapsed());
  for (const std::string& path : counts.reproducers) std::printf("reproducer: %s\n", path.c_str());
  return counts.findings() == 0 ? 0 : 1;
}
