#pragma once
/// @file
/// A fuzzing campaign: inputs 0..n-1 of a seed, each run isolated and judged; every finding is counted and
/// the first ones of each kind are written as reproducers.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "input_generator.hpp"
#include "isolated_run.hpp"

namespace flexmbd {
namespace fuzz {

struct CampaignOptions {
  uint64_t seed = 1;
  uint64_t inputs = 1000;
  double max_seconds = 0.0;  ///< stop early after this wall time; 0 for no limit
  std::string out_dir;       ///< reproducers go here (created if missing)
  IsolationLimits limits;
  size_t reproducers_per_kind = 20;  ///< findings of a kind past this are counted, not written
};

struct CampaignCounts {
  uint64_t inputs = 0;
  uint64_t completed = 0, config_errors = 0, solver_errors = 0;        ///< accepted outcomes
  uint64_t crashes = 0, hangs = 0, wrong_exceptions = 0, bad_messages = 0;  ///< findings
  std::vector<std::string> reproducers;  ///< paths of the written reproducers' notes (.txt)
  uint64_t findings() const { return crashes + hangs + wrong_exceptions + bad_messages; }
};

/// Called every `every` inputs with the counts so far (progress lines of a long run).
struct Progress {
  uint64_t every = 0;
  std::function<void(const CampaignCounts&)> report;
};

/// What a note beside an input's files says: its seed, index and channel, and how to replay it from `stem`.
std::string DescribeInput(uint64_t seed, uint64_t index, const FuzzInput& input, const std::string& stem);

/// Writes `stem`.urdf, `stem`.yaml and the note `stem`.txt; throws std::runtime_error if a write fails.
void WriteInputFiles(const std::string& stem, const FuzzInput& input, const std::string& note);

CampaignCounts RunCampaign(const InputGenerator& generator, const CampaignOptions& options,
                           const Progress& progress = {});

}  // namespace fuzz
}  // namespace flexmbd
