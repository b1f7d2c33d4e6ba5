#pragma once
/// @file
/// The cases mutations start from: test/fuzz/seeds.txt lists them as URDF and YAML file pairs.

#include <string>
#include <vector>

namespace flexmbd {
namespace fuzz {

struct SeedCase {
  std::string name;  ///< "<urdf path> + <yaml path>", as listed
  std::string urdf;  ///< URDF text
  std::string yaml;  ///< YAML text; "" for a URDF alone
};

/// Reads the list at `list_path` ("<urdf> <yaml>" per line, paths relative to `root`, "-" for no YAML, '#'
/// comments) and the files it names. Throws std::runtime_error for a list that cannot be read or a bad line,
/// ConfigError (ReadTextFile) for a seed file that cannot be read.
std::vector<SeedCase> ReadSeedCorpus(const std::string& root, const std::string& list_path);

}  // namespace fuzz
}  // namespace flexmbd
