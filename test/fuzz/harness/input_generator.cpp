#include "input_generator.hpp"

#include <utility>

#include "text_mutator.hpp"

namespace flexmbd {
namespace fuzz {
namespace {

std::vector<YAML::Node> ParseTrees(const std::vector<SeedCase>& seeds) {
  std::vector<YAML::Node> trees;
  for (const SeedCase& seed : seeds) {
    try {
      trees.push_back(YAML::Load(seed.yaml));
    } catch (const YAML::Exception&) {
      trees.push_back(YAML::Node());  // a seed with a syntax error is mutated as text only
    }
  }
  return trees;
}

std::vector<std::string> UrdfTexts(const std::vector<SeedCase>& seeds) {
  std::vector<std::string> texts;
  for (const SeedCase& seed : seeds) texts.push_back(seed.urdf);
  return texts;
}

// SplitMix64 of the pair: independent, well-mixed generator seeds for neighbouring inputs.
uint64_t Mix(uint64_t seed, uint64_t index) {
  uint64_t z = seed * 0x9E3779B97F4A7C15ull + index + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

InputGenerator::InputGenerator(std::vector<SeedCase> seeds)
    : seeds_(std::move(seeds)), trees_(ParseTrees(seeds_)), yaml_mutator_(trees_), urdf_mutator_(UrdfTexts(seeds_)) {}

FuzzInput InputGenerator::Make(uint64_t seed, uint64_t index) const {
  Rng rng(Mix(seed, index));
  const size_t which = Pick(&rng, seeds_.size());
  const SeedCase& base = seeds_[which];
  FuzzInput input;
  input.channel = Chance(&rng, 0.2) ? Channel::kParamTree : Channel::kFiles;

  YAML::Node tree = YAML::Clone(trees_[which]);  // a seed without YAML gets one from grafts
  tinyxml2::XMLDocument urdf;
  const bool urdf_tree = urdf.Parse(base.urdf.c_str(), base.urdf.size()) == tinyxml2::XML_SUCCESS;
  bool yaml_changed = false, urdf_changed = false;
  std::vector<int> text_mutations;  // 0: URDF text, 1: YAML text; applied after the trees are written out
  const size_t mutations = 1 + Pick(&rng, 4);
  for (size_t k = 0; k < mutations; ++k) {
    const double kind = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    if (kind < 0.55) {
      yaml_mutator_.Mutate(&tree, &rng);
      yaml_changed = true;
    } else if (kind < 0.9 && urdf_tree) {
      urdf_mutator_.Mutate(&urdf, &rng);
      urdf_changed = true;
    } else {
      text_mutations.push_back(Chance(&rng, 0.5) ? 0 : 1);
    }
  }
  input.urdf = urdf_changed ? PrintXml(urdf) : base.urdf;
  input.yaml = yaml_changed ? EmitYaml(tree) : base.yaml;
  for (int target : text_mutations) {
    MutateText(target == 0 ? &input.urdf : &input.yaml, target == 1, &rng);
  }
  return input;
}

}  // namespace fuzz
}  // namespace flexmbd
