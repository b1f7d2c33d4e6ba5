#pragma once
/// @file
/// Structure-aware mutation of a YAML extension-parameter tree: the tree stays YAML and mostly keeps the
/// schema's shape, so the loader's checks past parsing are reached.

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "hostile_values.hpp"

namespace flexmbd {
namespace fuzz {

class YamlMutator {
 public:
  /// @param[in] donors the seed trees: keys and subtrees to graft, renamed keys to borrow
  explicit YamlMutator(const std::vector<YAML::Node>& donors);

  /// Applies one mutation to `root` in place: a hostile number, a string where a number belongs, a swapped
  /// type, a dropped, duplicated or renamed key or entry, an emptied collection, or a subtree grafted from a
  /// donor (a joint's friction block on a beam, a solver key under output).
  void Mutate(YAML::Node* root, Rng* rng) const;

 private:
  struct Graft {
    std::string key;
    YAML::Node value;
  };
  std::vector<Graft> grafts_;
};

/// The tree as YAML text (block style).
std::string EmitYaml(const YAML::Node& root);

}  // namespace fuzz
}  // namespace flexmbd
