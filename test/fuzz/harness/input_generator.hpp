#pragma once
/// @file
/// Makes fuzz input number k of a campaign from its seed alone: a seed case with one to four mutations of its
/// YAML tree, its URDF tree or their text, sent through the runner's file channel or the node's parameters.

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <vector>

#include "fuzz_input.hpp"
#include "seed_corpus.hpp"
#include "urdf_mutator.hpp"
#include "yaml_mutator.hpp"

namespace flexmbd {
namespace fuzz {

class InputGenerator {
 public:
  explicit InputGenerator(std::vector<SeedCase> seeds);

  /// Input `index` of the campaign `seed`: the same pair always gives the same input, so any input can be
  /// made again without the ones before it.
  FuzzInput Make(uint64_t seed, uint64_t index) const;

 private:
  std::vector<SeedCase> seeds_;
  std::vector<YAML::Node> trees_;  ///< each seed's YAML parsed (null if it does not parse)
  YamlMutator yaml_mutator_;
  UrdfMutator urdf_mutator_;
};

}  // namespace fuzz
}  // namespace flexmbd
