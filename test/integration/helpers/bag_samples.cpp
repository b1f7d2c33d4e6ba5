#include "bag_samples.hpp"

#include <rosbag/bag.h>
#include <rosbag/view.h>

namespace flexmbd {
namespace test {
namespace {

template <typename Message>
void ReadTopic(const rosbag::Bag& bag, const std::string& topic, std::vector<Message>* messages) {
  for (const rosbag::MessageInstance& instance : rosbag::View(bag, rosbag::TopicQuery(topic))) {
    messages->push_back(*instance.instantiate<Message>());
  }
}

}  // namespace

Samples ReadBagSamples(const std::string& path, const std::string& node_name) {
  rosbag::Bag bag(path, rosbag::bagmode::Read);
  const std::string prefix = "/" + node_name + "/";
  Samples samples;
  ReadTopic(bag, "/joint_states", &samples.joint_states);
  ReadTopic(bag, prefix + "energy", &samples.energy);
  ReadTopic(bag, prefix + "reactions", &samples.reactions);
  ReadTopic(bag, prefix + "solver", &samples.solver);
  ReadTopic(bag, prefix + "beam_loads", &samples.beam_loads);
  ReadTopic(bag, prefix + "aero_loads", &samples.aero_loads);
  ReadTopic(bag, "/tf", &samples.transforms);
  return samples;
}

}  // namespace test
}  // namespace flexmbd
