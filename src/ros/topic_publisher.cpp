#include "flexmbd/ros/topic_publisher.hpp"

#include <rosgraph_msgs/Clock.h>

#include <algorithm>

namespace flexmbd {
namespace ros {
namespace {

// Messages queued per subscriber before the oldest is dropped: at real_time_factor 0 the solver produces
// samples in bursts far faster than a subscriber takes them, and a whole short run fits in the queue.
constexpr uint32_t kSampleQueueSize = 10000;
constexpr uint32_t kClockQueueSize = 100;

template <typename Message>
::ros::Publisher AdvertiseSamples(::ros::NodeHandle& handle, const std::string& topic,
                                  const std::function<void()>& on_connect) {
  return handle.advertise<Message>(topic, kSampleQueueSize,
                                   [on_connect](const ::ros::SingleSubscriberPublisher&) { on_connect(); });
}

}  // namespace

TopicNames ResolveTopicNames(const ::ros::NodeHandle& node, const ::ros::NodeHandle& private_node) {
  return TopicNames{node.resolveName(kJointStatesTopic),
                    private_node.resolveName(kEnergyTopic),
                    private_node.resolveName(kReactionsTopic),
                    private_node.resolveName(kSolverTopic),
                    private_node.resolveName(kContactsTopic),
                    private_node.resolveName(kFrictionTopic),
                    private_node.resolveName(kBeamLoadsTopic),
                    node.resolveName(kTfTopic),
                    private_node.resolveName(kMarkersTopic)};
}

TopicPublisher::TopicPublisher(::ros::NodeHandle& node, ::ros::NodeHandle& private_node, const Model& model,
                               bool publish_clock, const std::function<void()>& on_connect)
    : joint_states_(AdvertiseSamples<sensor_msgs::JointState>(node, kJointStatesTopic, on_connect)),
      energy_(AdvertiseSamples<Energy>(private_node, kEnergyTopic, on_connect)),
      reactions_(AdvertiseSamples<JointReactions>(private_node, kReactionsTopic, on_connect)),
      solver_(AdvertiseSamples<SolverStep>(private_node, kSolverTopic, on_connect)),
      tf_(node.advertise<tf2_msgs::TFMessage>(kTfTopic, kSampleQueueSize)),
      markers_(private_node.advertise<visualization_msgs::MarkerArray>(kMarkersTopic, 1, /*latch=*/true)) {
  if (!model.stops().empty()) {
    contacts_ = AdvertiseSamples<JointContactArray>(private_node, kContactsTopic, on_connect);
  }
  if (!model.frictions().empty()) {
    friction_ = AdvertiseSamples<JointFrictionArray>(private_node, kFrictionTopic, on_connect);
  }
  if (!model.beam_stations().empty()) {
    beam_loads_ = AdvertiseSamples<BeamLoadsArray>(private_node, kBeamLoadsTopic, on_connect);
  }
  if (publish_clock) clock_ = node.advertise<rosgraph_msgs::Clock>(kClockTopic, kClockQueueSize);
  markers_.publish(ToBodyMarkers(model));
}

void TopicPublisher::Write(const SampleMessages& messages) {
  if (!::ros::ok()) return;
  if (clock_) {
    rosgraph_msgs::Clock clock;
    clock.clock = messages.joint_state.header.stamp;
    clock_.publish(clock);
  }
  if (messages.has_transforms) tf_.publish(messages.transforms);
  joint_states_.publish(messages.joint_state);
  energy_.publish(messages.energy);
  reactions_.publish(messages.reactions);
  solver_.publish(messages.solver);
  if (contacts_) contacts_.publish(messages.contacts);
  if (friction_) friction_.publish(messages.friction);
  if (beam_loads_) beam_loads_.publish(messages.beam_loads);
}

bool TopicPublisher::HasSubscribers() const {
  for (const ::ros::Publisher* publisher :
       {&joint_states_, &energy_, &reactions_, &solver_, &contacts_, &friction_, &beam_loads_, &tf_, &markers_,
        &clock_}) {
    if (*publisher && publisher->getNumSubscribers() > 0) return true;
  }
  return false;
}

int TopicPublisher::MinSampleSubscribers() const {
  uint32_t fewest = std::min({joint_states_.getNumSubscribers(), energy_.getNumSubscribers(),
                              reactions_.getNumSubscribers(), solver_.getNumSubscribers()});
  for (const ::ros::Publisher* optional : {&contacts_, &friction_, &beam_loads_}) {
    if (*optional) fewest = std::min(fewest, optional->getNumSubscribers());
  }
  return static_cast<int>(fewest);
}

}  // namespace ros
}  // namespace flexmbd
