#pragma once
// Reads the sample topics of a bag written by the node or the runner.

#include <string>

#include "samples.hpp"

namespace flexmbd {
namespace test {

/// The samples recorded under /joint_states, /tf and /<node_name>/{energy,reactions,solver,beam_loads,aero_loads},
/// in bag order.
/// Throws rosbag::BagException if the bag cannot be read (e.g. it was not closed).
Samples ReadBagSamples(const std::string& path, const std::string& node_name);

}  // namespace test
}  // namespace flexmbd
