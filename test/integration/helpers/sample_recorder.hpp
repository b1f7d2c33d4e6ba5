#pragma once
// Subscribes to a node's sample topics and keeps every message, for tests that compare them with a bag, a
// CSV or expectations. Callbacks run in a spinner thread of their own; tests wait with timeouts.

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "samples.hpp"

namespace flexmbd {
namespace test {

/// True once every sample topic (joint_states, energy, reactions, solver) holds a message stamped at or after
/// `t` [s].
bool EverySampleTopicReached(const Samples& samples, double t);

class SampleRecorder {
 public:
  /// Subscribes to joint_states and /tf (root namespace) and /<node_name>/{energy,reactions,solver,contacts,
  /// friction,beam_loads,aero_loads} (the last four are published only for models with stops, friction, beam
  /// stations, aero sections or strip stations).
  explicit SampleRecorder(const std::string& node_name);
  ~SampleRecorder();

  /// Waits until `done(samples)` holds, re-checking after every message; false if `timeout` passes first.
  bool WaitUntil(const std::function<bool(const Samples&)>& done, std::chrono::milliseconds timeout);

  /// Waits until every sample topic has delivered a message stamped at or after `t` [s].
  bool WaitForTime(double t, std::chrono::milliseconds timeout);

  /// A copy of what has arrived.
  Samples Snapshot() const;

 private:
  template <typename Message>
  ::ros::Subscriber Subscribe(const std::string& topic, std::vector<Message> Samples::*field);

  ::ros::NodeHandle handle_;
  ::ros::CallbackQueue queue_;
  ::ros::AsyncSpinner spinner_;
  mutable std::mutex mutex_;
  std::condition_variable arrived_;
  Samples samples_;
  std::vector<::ros::Subscriber> subscribers_;
};

}  // namespace test
}  // namespace flexmbd
