#include "seed_corpus.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "flexmbd/io/text_file.hpp"

namespace flexmbd {
namespace fuzz {

std::vector<SeedCase> ReadSeedCorpus(const std::string& root, const std::string& list_path) {
  std::ifstream list(list_path);
  if (!list) throw std::runtime_error("fuzz: cannot read the seed list '" + list_path + "'");
  std::vector<SeedCase> seeds;
  for (std::string line; std::getline(list, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string urdf, yaml;
    if (!(fields >> urdf >> yaml)) throw std::runtime_error("fuzz: " + list_path + ": not '<urdf> <yaml>': " + line);
    seeds.push_back(SeedCase{urdf + " + " + yaml, ReadTextFile(root + "/" + urdf, "seed URDF file"),
                             yaml == "-" ? "" : ReadTextFile(root + "/" + yaml, "seed YAML file")});
  }
  if (seeds.empty()) throw std::runtime_error("fuzz: no seed cases in '" + list_path + "'");
  return seeds;
}

}  // namespace fuzz
}  // namespace flexmbd
