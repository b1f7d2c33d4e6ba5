#include "campaign.hpp"

#include <sys/stat.h>

#include <chrono>
#include <fstream>
#include <map>
#include <stdexcept>

#include "verdict.hpp"

namespace flexmbd {
namespace fuzz {
namespace {

void WriteFile(const std::string& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  if (!file.flush()) throw std::runtime_error("fuzz: cannot write '" + path + "'");
}

// <dir>/<kind>_<seed>_<index>.{urdf,yaml,txt}: the pair to replay (test/fuzz/README.md) and a note.
std::string WriteReproducer(const CampaignOptions& options, uint64_t index, const FuzzInput& input,
                            const Verdict& verdict) {
  const std::string stem = options.out_dir + "/" + FindingName(verdict.finding) + "_" + std::to_string(options.seed) +
                           "_" + std::to_string(index);
  WriteInputFiles(stem, input, std::string(FindingName(verdict.finding)) + ": " + verdict.detail + "\n" +
                                   DescribeInput(options.seed, index, input, stem));
  return stem + ".txt";
}

void Count(const IsolatedResult& isolated, const Verdict& verdict, CampaignCounts* counts) {
  switch (verdict.finding) {
    case Finding::kCrash:
      ++counts->crashes;
      return;
    case Finding::kHang:
      ++counts->hangs;
      return;
    case Finding::kWrongException:
      ++counts->wrong_exceptions;
      return;
    case Finding::kBadMessage:
      ++counts->bad_messages;
      return;
    case Finding::kNone:
      break;
  }
  switch (isolated.result.outcome) {
    case Outcome::kConfigError:
      ++counts->config_errors;
      return;
    case Outcome::kSolverError:
      ++counts->solver_errors;
      return;
    default:
      ++counts->completed;
      return;
  }
}

}  // namespace

std::string DescribeInput(uint64_t seed, uint64_t index, const FuzzInput& input, const std::string& stem) {
  const bool params = input.channel == Channel::kParamTree;
  return "seed " + std::to_string(seed) + ", input " + std::to_string(index) + ", channel " +
         (params ? "parameter tree" : "files") + "\nreplay: fuzz_config --replay " + stem + ".urdf " + stem + ".yaml" +
         (params ? " --param-tree" : "") + "\n";
}

void WriteInputFiles(const std::string& stem, const FuzzInput& input, const std::string& note) {
  WriteFile(stem + ".urdf", input.urdf);
  WriteFile(stem + ".yaml", input.yaml);
  WriteFile(stem + ".txt", note);
}

CampaignCounts RunCampaign(const InputGenerator& generator, const CampaignOptions& options, const Progress& progress) {
  mkdir(options.out_dir.c_str(), 0755);
  const auto start = std::chrono::steady_clock::now();
  CampaignCounts counts;
  std::map<Finding, size_t> written;
  for (uint64_t index = 0; index < options.inputs; ++index) {
    if (options.max_seconds > 0.0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > options.max_seconds) {
      break;
    }
    const FuzzInput input = generator.Make(options.seed, index);
    const IsolatedResult isolated = RunIsolated([&] { return LoadAndStep(input); }, options.limits);
    const Verdict verdict = Judge(isolated);
    Count(isolated, verdict, &counts);
    ++counts.inputs;
    if (verdict.finding != Finding::kNone && written[verdict.finding]++ < options.reproducers_per_kind) {
      counts.reproducers.push_back(WriteReproducer(options, index, input, verdict));
    }
    if (progress.every > 0 && counts.inputs % progress.every == 0) progress.report(counts);
  }
  return counts;
}

}  // namespace fuzz
}  // namespace flexmbd
