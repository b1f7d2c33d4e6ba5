#include "flexmbd/ros/topic_names.hpp"

namespace flexmbd {
namespace ros {

TopicNames DefaultTopicNames() {
  const std::string private_prefix = std::string(kDefaultNodeName) + "/";
  return TopicNames{std::string("/") + kJointStatesTopic,
                    private_prefix + kEnergyTopic,
                    private_prefix + kReactionsTopic,
                    private_prefix + kSolverTopic,
                    private_prefix + kContactsTopic,
                    private_prefix + kFrictionTopic,
                    private_prefix + kBeamLoadsTopic,
                    private_prefix + kAeroLoadsTopic,
                    kTfTopic,
                    kTfStaticTopic,
                    private_prefix + kMarkersTopic};
}

}  // namespace ros
}  // namespace flexmbd
