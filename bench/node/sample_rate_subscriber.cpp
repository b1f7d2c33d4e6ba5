// Benchmark subscriber for scripts/bench_node.sh: receives a node's sample topics on loopback (the four
// every node has, /tf, and ~contacts, ~friction and ~beam_loads, which carry messages where the model has stops,
// frictional joints or beam stations; a node started with ~wait_for_subscribers waits for each) and reports how many samples arrived, how many were lost (gaps in
// header.seq, the sample index) and at what rate.
//   sample_rate_subscriber NODE_NAME [IDLE_SECONDS]
// Ends once messages have stopped for IDLE_SECONDS (default 3) after the first one; prints one line:
//   received N samples (joint_states), lost L, in S s: R samples/s

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

#include "flexmbd/ros/message_conversions.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// Counts one topic's messages and the gaps in their sample index.
template <typename Message>
struct TopicCounter {
  using MessageType = Message;
  long received = 0;
  long lost = 0;
  long next_seq = 0;
  void Count(const typename Message::ConstPtr& message) {
    lost += static_cast<long>(message->header.seq) - next_seq;
    next_seq = static_cast<long>(message->header.seq) + 1;
    ++received;
  }
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "sample_rate_subscriber", ros::init_options::AnonymousName);
  if (argc < 2) {
    std::fputs("usage: sample_rate_subscriber NODE_NAME [IDLE_SECONDS]\n", stderr);
    return 1;
  }
  const std::string prefix = std::string("/") + argv[1] + "/";
  const double idle_seconds = argc > 2 ? std::stod(argv[2]) : 3.0;
  ros::NodeHandle handle;
  // as large as the node's own queue: the subscriber takes bursts without dropping
  constexpr uint32_t kQueueSize = 10000;
  TopicCounter<sensor_msgs::JointState> joint_states;
  TopicCounter<flexmbd::Energy> energy;
  TopicCounter<flexmbd::JointReactionArray> reactions;
  TopicCounter<flexmbd::SolverStep> solver;
  TopicCounter<flexmbd::JointContactArray> contacts;
  TopicCounter<flexmbd::JointFrictionArray> friction;
  TopicCounter<flexmbd::BeamLoadsArray> beam_loads;
  Clock::time_point first, last;
  const auto touch = [&] {
    last = Clock::now();
    if (joint_states.received + energy.received + reactions.received + solver.received == 1) first = last;
  };
  const auto subscribe = [&](const std::string& topic, auto* counter) {
    using Message = typename std::remove_pointer_t<decltype(counter)>::MessageType;
    return handle.subscribe<Message>(topic, kQueueSize,
                                     boost::function<void(const typename Message::ConstPtr&)>(
                                         [counter, &touch](const typename Message::ConstPtr& m) {
                                           counter->Count(m);
                                           touch();
                                         }),
                                     ros::VoidConstPtr());
  };
  const std::vector<ros::Subscriber> subscribers{
      subscribe("/joint_states", &joint_states), subscribe(prefix + "energy", &energy),
      subscribe(prefix + "reactions", &reactions), subscribe(prefix + "solver", &solver),
      subscribe(prefix + "contacts", &contacts), subscribe(prefix + "friction", &friction),
      subscribe(prefix + "beam_loads", &beam_loads),
      // /tf messages carry no sample index: received, not counted
      handle.subscribe<tf2_msgs::TFMessage>("/tf", kQueueSize,
                                            boost::function<void(const tf2_msgs::TFMessage::ConstPtr&)>(
                                                [&touch](const tf2_msgs::TFMessage::ConstPtr&) { touch(); }),
                                            ros::VoidConstPtr())};
  const ros::WallDuration poll(0.01);
  while (ros::ok()) {
    ros::getGlobalCallbackQueue()->callAvailable(poll);
    const bool started = joint_states.received > 0;
    if (started && std::chrono::duration<double>(Clock::now() - last).count() > idle_seconds) break;
  }
  const double seconds = std::chrono::duration<double>(last - first).count();
  const long lost =
      joint_states.lost + energy.lost + reactions.lost + solver.lost + contacts.lost + friction.lost + beam_loads.lost;
  std::printf("received %ld samples (joint_states), lost %ld (all topics), in %.3f s: %.0f samples/s\n",
              joint_states.received, lost, seconds, seconds > 0 ? joint_states.received / seconds : 0.0);
  return 0;
}
