#include "yaml_mutator.hpp"

#include <utility>

namespace flexmbd {
namespace fuzz {
namespace {

// Strings that are not what any field expects: unknown names (broken references), names that would break
// a CSV header, enum values of the wrong field.
const std::vector<std::string> kHostileStrings = {
    "no_such_link", "no_such_joint", "a,b", "line\nbreak", "", "hertz", "cosine_ramp", "eigen", "static",
    "coulomb_stick", "rigid", "~", "[", "yes", std::string(300, 'x')};

// Every node of `root`, collections included, in document order; iterative so a deep tree cannot overflow.
std::vector<YAML::Node> CollectNodes(const YAML::Node& root) {
  std::vector<YAML::Node> nodes;
  std::vector<YAML::Node> pending = {root};
  while (!pending.empty()) {
    YAML::Node node = pending.back();
    pending.pop_back();
    nodes.push_back(node);
    if (node.IsMap()) {
      for (auto entry : node) pending.push_back(entry.second);
    } else if (node.IsSequence()) {
      for (auto entry : node) pending.push_back(entry);
    }
  }
  return nodes;
}

std::vector<YAML::Node> OfType(const std::vector<YAML::Node>& nodes, YAML::NodeType::value type) {
  std::vector<YAML::Node> found;
  for (const YAML::Node& node : nodes) {
    if (node.Type() == type) found.push_back(node);
  }
  return found;
}

std::string Typo(const std::string& key, Rng* rng) {
  switch (Pick(rng, 4)) {
    case 0:
      return key + "_";
    case 1:
      return key.empty() ? "x" : key.substr(0, key.size() - 1);
    case 2:
      return key + "," + key;
    default:
      return "no_such_" + key;
  }
}

// The map `map` with the entry at `index` renamed to `key`, or left out if `drop`; order kept.
YAML::Node RebuiltMap(const YAML::Node& map, size_t index, const std::string& key, bool drop) {
  YAML::Node rebuilt(YAML::NodeType::Map);
  size_t k = 0;
  for (auto entry : map) {
    if (k++ != index) {
      rebuilt[entry.first] = entry.second;
    } else if (!drop) {
      rebuilt[key] = entry.second;
    }
  }
  return rebuilt;
}

YAML::Node SequenceWithout(const YAML::Node& sequence, size_t index) {
  YAML::Node rebuilt(YAML::NodeType::Sequence);
  for (size_t k = 0; k < sequence.size(); ++k) {
    if (k != index) rebuilt.push_back(sequence[k]);
  }
  return rebuilt;
}

YAML::Node OtherType(const YAML::Node& node, Rng* rng) {
  switch (Pick(rng, 4)) {
    case 0:
      return YAML::Node(YAML::NodeType::Map);
    case 1: {
      YAML::Node list(YAML::NodeType::Sequence);
      list.push_back(node.IsScalar() ? node.Scalar() : "1");
      list.push_back("2");
      return list;
    }
    case 2:
      return YAML::Node(YAML::NodeType::Null);
    default:
      return YAML::Node(node.IsScalar() ? "[" + node.Scalar() + "]" : "1");
  }
}

void MutateScalar(YAML::Node node, Rng* rng) {
  if (Chance(rng, 0.8)) {
    node = HostileNumber(node.Scalar(), rng);
  } else {
    node = kHostileStrings[Pick(rng, kHostileStrings.size())];
  }
}

void MutateMap(YAML::Node map, const std::string& donor_key, Rng* rng) {
  if (map.size() == 0) return;
  const size_t index = Pick(rng, map.size());
  auto entry = map.begin();
  std::advance(entry, index);
  const std::string key = entry->first.Scalar();
  switch (Pick(rng, 4)) {
    case 0:
      map = RebuiltMap(map, index, "", true);
      break;
    case 1:
      map = RebuiltMap(map, index, Chance(rng, 0.5) ? Typo(key, rng) : donor_key,
                       false);
      break;
    case 2:
      map[Typo(key, rng)] = YAML::Clone(entry->second);
      break;
    default:
      map = YAML::Node(YAML::NodeType::Map);
      break;
  }
}

void MutateSequence(YAML::Node sequence, Rng* rng) {
  if (sequence.size() == 0 || Chance(rng, 0.25)) {
    sequence.push_back(HostileNumber("1", rng));
    return;
  }
  const size_t index = Pick(rng, sequence.size());
  if (Chance(rng, 0.5)) {
    sequence = SequenceWithout(sequence, index);
  } else {
    sequence.push_back(YAML::Clone(sequence[index]));
  }
}

}  // namespace

YamlMutator::YamlMutator(const std::vector<YAML::Node>& donors) {
  for (const YAML::Node& donor : donors) {
    for (const YAML::Node& node : CollectNodes(donor)) {
      if (!node.IsMap()) continue;
      for (auto entry : node) grafts_.push_back(Graft{entry.first.Scalar(), entry.second});
    }
  }
}

void YamlMutator::Mutate(YAML::Node* root, Rng* rng) const {
  if (!root->IsMap() && !root->IsSequence() && !root->IsScalar()) *root = YAML::Node(YAML::NodeType::Map);
  const std::vector<YAML::Node> nodes = CollectNodes(*root);

  switch (Pick(rng, 5)) {
    case 0: {  // a value: hostile number or string
      std::vector<YAML::Node> scalars = OfType(nodes, YAML::NodeType::Scalar);
      if (!scalars.empty()) MutateScalar(scalars[Pick(rng, scalars.size())], rng);
      return;
    }
    case 1: {  // a key dropped, renamed, duplicated, or its map emptied
      std::vector<YAML::Node> maps = OfType(nodes, YAML::NodeType::Map);
      const std::string donor_key = grafts_.empty() ? "solver" : grafts_[Pick(rng, grafts_.size())].key;
      if (!maps.empty()) MutateMap(maps[Pick(rng, maps.size())], donor_key, rng);
      return;
    }
    case 2: {  // a list entry dropped, duplicated or a hostile one added
      std::vector<YAML::Node> sequences = OfType(nodes, YAML::NodeType::Sequence);
      if (!sequences.empty()) MutateSequence(sequences[Pick(rng, sequences.size())], rng);
      return;
    }
    case 3: {  // any node replaced by another type
      YAML::Node node = nodes[Pick(rng, nodes.size())];
      node = OtherType(node, rng);
      return;
    }
    default: {  // a donor's key and subtree grafted into a map
      std::vector<YAML::Node> maps = OfType(nodes, YAML::NodeType::Map);
      if (maps.empty() || grafts_.empty()) return;
      const Graft& graft = grafts_[Pick(rng, grafts_.size())];
      maps[Pick(rng, maps.size())][graft.key] = YAML::Clone(graft.value);
      return;
    }
  }
}

std::string EmitYaml(const YAML::Node& root) {
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

}  // namespace fuzz
}  // namespace flexmbd
