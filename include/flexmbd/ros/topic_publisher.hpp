#pragma once
/// @file
/// Publishes the messages of each sample on the node's topics (docs/ros.md). roscpp queues every message per
/// subscriber and sends it from its own thread, so publishing never waits for a subscriber; that thread is
/// woken once for a batch of samples (QueuedTopic), at the latest by EndBatch.

#include <ros/ros.h>

#include <functional>
#include <string>
#include <vector>

#include "flexmbd/ros/message_sink.hpp"
#include "flexmbd/ros/queued_topic.hpp"
#include "flexmbd/ros/topic_names.hpp"

namespace flexmbd {
namespace ros {

/// The topic names of the node with handles `node` and `private_node` ("~"), after remapping.
TopicNames ResolveTopicNames(const ::ros::NodeHandle& node, const ::ros::NodeHandle& private_node);

class TopicPublisher : public MessageSink {
 public:
  /// Advertises `joint_states` and `/tf` in `node`'s namespace, `~energy`, `~reactions`, `~solver`,
  /// `~contacts` if `model` has stops, `~friction` if it has frictional joints, `~beam_loads` if it has beam
  /// stations (output.beam_stations), `~aero_loads` if it has aero sections or strip stations, and the latched
  /// `~markers` (ToBodyMarkers, published once, here) in `private_node`'s, the latched `/tf_static` (published once,
  /// here) unless `static_transforms` is empty, and `/clock` if `publish_clock`. `on_connect` is called
  /// (from a spinner thread) whenever a subscriber connects to a sample topic.
  TopicPublisher(::ros::NodeHandle& node, ::ros::NodeHandle& private_node, const Model& model,
                 const tf2_msgs::TFMessage& static_transforms, bool publish_clock,
                 const std::function<void()>& on_connect);

  /// Publishes while ROS is up (after a shutdown it does nothing).
  void Write(const SampleMessages& messages) override;

  /// Whether /clock is advertised.
  bool publishes_clock() const { return static_cast<bool>(clock_); }

  /// Publishes simulated time `t` [s] on /clock at once (from the run loop: ClockTicks paces it).
  void PublishClock(double t);

  /// Wakes roscpp's sender for the samples written since it was last woken.
  void EndBatch() override;

  /// Fewest subscribers over the sample topics (joint_states, ~energy, ~reactions, ~solver, /tf, and ~contacts,
  /// ~friction, ~beam_loads, ~aero_loads where advertised).
  int MinSampleSubscribers() const;

  /// The sample topics with fewer than `count` subscribers, by resolved name: what a start that waits for
  /// subscribers is waiting for.
  std::vector<std::string> SampleTopicsBelow(int count) const;

  /// Every topic the samples, the markers and the static transforms go to, by resolved name (not /clock): what
  /// `record:=` records (scripts/record_node_topics.py reads them from ~recorded_topics).
  std::vector<std::string> RecordedTopics() const;

  /// True if any topic has a subscriber.
  bool HasSubscribers() const;

 private:
  // The topics every sample goes to: joint_states, ~energy, ~reactions, ~solver, /tf and those advertised of
  // ~contacts, ~friction, ~beam_loads, ~aero_loads. A subscriber to /tf that connects late would miss the link frames
  // of a short run at real_time_factor 0 (it happened to the node_topics rostest on a loaded machine).
  std::vector<const QueuedTopic*> SampleTopics() const;

  QueuedTopic joint_states_, energy_, reactions_, solver_, contacts_, friction_, beam_loads_, aero_loads_, tf_;
  ::ros::Publisher clock_;       ///< none without /use_sim_time
  ::ros::Publisher markers_;     ///< latched, published once
  ::ros::Publisher tf_static_;   ///< latched, published once; none without static transforms
  int unsent_samples_ = 0;    ///< samples queued since the sender was last woken
};

}  // namespace ros
}  // namespace flexmbd
