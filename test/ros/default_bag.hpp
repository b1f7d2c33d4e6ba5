#pragma once
// A bag as the runner and the node record it by default: under the topics of the default node name.

#include <string>

#include "../integration/helpers/bag_samples.hpp"
#include "flexmbd/ros/topic_names.hpp"

namespace flexmbd {
namespace test {

/// The samples of the bag at `path`, read from the topics under kDefaultNodeName (without its leading '/').
inline Samples ReadDefaultBag(const std::string& path) {
  return ReadBagSamples(path, std::string(ros::kDefaultNodeName).substr(1));
}

}  // namespace test
}  // namespace flexmbd
