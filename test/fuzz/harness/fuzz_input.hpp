#pragma once
/// @file
/// One input of the fuzzer: the texts of a URDF and a YAML file, and how they reach the loader.

#include <string>

namespace flexmbd {
namespace fuzz {

/// The runner's files, or the node's parameter tree (the YAML converted as rosparam stores it).
enum class Channel { kFiles, kParamTree };

struct FuzzInput {
  std::string urdf;  ///< URDF text
  std::string yaml;  ///< YAML text; "" loads the URDF alone on the file channel
  Channel channel = Channel::kFiles;
};

}  // namespace fuzz
}  // namespace flexmbd
