#include "flexmbd/ros/topic_publisher.hpp"

#include <rosgraph_msgs/Clock.h>

#include <algorithm>
#include <limits>

namespace flexmbd {
namespace ros {
namespace {

// Messages queued per subscriber before the oldest is dropped: at real_time_factor 0 the solver produces
// samples in bursts far faster than a subscriber takes them, and a whole short run fits in the queue.
constexpr uint32_t kSampleQueueSize = 10000;
constexpr uint32_t kClockQueueSize = 100;

// Samples queued on the topics before roscpp's sender is woken for them (Write, EndBatch): one wake-up
// (two system calls) for 64 samples, not one for each of their messages, while the sender still starts on
// a long batch before it ends.
constexpr int kSamplesPerWake = 64;

template <typename Message>
QueuedTopic AdvertiseSamples(::ros::NodeHandle& handle, const std::string& topic,
                             const std::function<void()>& on_connect) {
  return QueuedTopic::Advertise<Message>(handle, topic, kSampleQueueSize,
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
                    private_node.resolveName(kAeroLoadsTopic),
                    node.resolveName(kTfTopic),
                    node.resolveName(kTfStaticTopic),
                    private_node.resolveName(kMarkersTopic)};
}

TopicPublisher::TopicPublisher(::ros::NodeHandle& node, ::ros::NodeHandle& private_node, const Model& model,
                               const tf2_msgs::TFMessage& static_transforms, bool publish_clock,
                               const std::function<void()>& on_connect)
    : joint_states_(AdvertiseSamples<sensor_msgs::JointState>(node, kJointStatesTopic, on_connect)),
      energy_(AdvertiseSamples<Energy>(private_node, kEnergyTopic, on_connect)),
      reactions_(AdvertiseSamples<JointReactionArray>(private_node, kReactionsTopic, on_connect)),
      solver_(AdvertiseSamples<SolverStep>(private_node, kSolverTopic, on_connect)),
      tf_(QueuedTopic::Advertise<tf2_msgs::TFMessage>(node, kTfTopic, kSampleQueueSize)),
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
  if (!model.aero_sections().empty() || !model.strip_stations().empty() || !model.aero_rotors().empty()) {
    aero_loads_ = AdvertiseSamples<AeroLoadsArray>(private_node, kAeroLoadsTopic, on_connect);
  }
  if (publish_clock) clock_ = node.advertise<rosgraph_msgs::Clock>(kClockTopic, kClockQueueSize);
  markers_.publish(ToBodyMarkers(model));
  if (!static_transforms.transforms.empty()) {
    tf_static_ = node.advertise<tf2_msgs::TFMessage>(kTfStaticTopic, 1, /*latch=*/true);
    tf_static_.publish(static_transforms);
  }
}

void TopicPublisher::Write(const SampleMessages& messages) {
  if (!::ros::ok()) return;
  bool queued = false;
  if (messages.has_transforms) queued |= tf_.Queue(messages.transforms);
  queued |= joint_states_.Queue(messages.joint_state);
  queued |= energy_.Queue(messages.energy);
  queued |= reactions_.Queue(messages.reactions);
  queued |= solver_.Queue(messages.solver);
  queued |= contacts_.Queue(messages.contacts);
  queued |= friction_.Queue(messages.friction);
  queued |= beam_loads_.Queue(messages.beam_loads);
  queued |= aero_loads_.Queue(messages.aero_loads);
  if (queued && ++unsent_samples_ >= kSamplesPerWake) EndBatch();
}

void TopicPublisher::PublishClock(double t) {
  rosgraph_msgs::Clock clock;
  clock.clock = ToStamp(t);
  clock_.publish(clock);
}

void TopicPublisher::EndBatch() {
  if (unsent_samples_ == 0) return;
  unsent_samples_ = 0;
  WakeTopicSender();
}

bool TopicPublisher::HasSubscribers() const {
  if (markers_.getNumSubscribers() > 0 || clock_.getNumSubscribers() > 0) return true;
  for (const QueuedTopic* topic :
       {&joint_states_, &energy_, &reactions_, &solver_, &contacts_, &friction_, &beam_loads_, &aero_loads_, &tf_}) {
    if (topic->NumSubscribers() > 0) return true;
  }
  return false;
}

std::vector<std::string> TopicPublisher::RecordedTopics() const {
  std::vector<std::string> names;
  for (const QueuedTopic* topic : SampleTopics()) names.push_back(topic->Name());
  names.push_back(markers_.getTopic());
  if (tf_static_) names.push_back(tf_static_.getTopic());
  return names;
}

std::vector<const QueuedTopic*> TopicPublisher::SampleTopics() const {
  std::vector<const QueuedTopic*> topics = {&joint_states_, &energy_, &reactions_, &solver_, &tf_};
  for (const QueuedTopic* optional : {&contacts_, &friction_, &beam_loads_, &aero_loads_}) {
    if (*optional) topics.push_back(optional);
  }
  return topics;
}

int TopicPublisher::MinSampleSubscribers() const {
  uint32_t fewest = std::numeric_limits<uint32_t>::max();
  for (const QueuedTopic* topic : SampleTopics()) fewest = std::min(fewest, topic->NumSubscribers());
  return static_cast<int>(fewest);
}

std::vector<std::string> TopicPublisher::SampleTopicsBelow(int count) const {
  std::vector<std::string> names;
  for (const QueuedTopic* topic : SampleTopics()) {
    if (static_cast<int>(topic->NumSubscribers()) < count) names.push_back(topic->Name());
  }
  return names;
}

}  // namespace ros
}  // namespace flexmbd
