#include "flexmbd/ros/command_input.hpp"

#include <ros/console.h>

#include <vector>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/message_text.hpp"
#include "flexmbd/ros/topic_names.hpp"

namespace flexmbd {
namespace ros {
namespace {

// A controller publishes its latest command: older ones queued behind it are stale.
constexpr uint32_t kQueueSize = 1;

const char* TopicOf(CommandInput::Kind kind) {
  return kind == CommandInput::Kind::kEffort ? kEffortCommandTopic : kPositionCommandTopic;
}

}  // namespace

CommandInput::CommandInput(::ros::NodeHandle private_node, const Model& model, double setpoint_time_constant)
    : model_(model), setpoint_time_constant_(setpoint_time_constant) {
  // no Nagle delay: a command is one small message that closes a control loop
  const ::ros::TransportHints hints = ::ros::TransportHints().tcpNoDelay();
  effort_subscriber_ = private_node.subscribe<sensor_msgs::JointState>(
      kEffortCommandTopic, kQueueSize,
      [this](const sensor_msgs::JointState::ConstPtr& message) { Receive(Kind::kEffort, *message); }, {}, hints);
  position_subscriber_ = private_node.subscribe<sensor_msgs::JointState>(
      kPositionCommandTopic, kQueueSize,
      [this](const sensor_msgs::JointState::ConstPtr& message) { Receive(Kind::kPosition, *message); }, {}, hints);
}

void CommandInput::Receive(Kind kind, const sensor_msgs::JointState& message) {
  const std::string topic = TopicOf(kind);
  const std::string field = kind == Kind::kEffort ? "effort" : "position";
  const std::vector<double>& values = kind == Kind::kEffort ? message.effort : message.position;
  if (values.size() != message.name.size()) {
    WarnOnce("~" + topic + ": " + std::to_string(values.size()) + " " + field + " values for " +
             std::to_string(message.name.size()) + " names; expected one " + field +
             " per name (message ignored)");
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  for (size_t k = 0; k < values.size(); ++k) {
    const int variable = model_.FindVariable(message.name[k]);
    if (variable < 0) {
      WarnOnce("~" + topic + ": name[" + std::to_string(k) + "] '" + message.name[k] +
               "' is not a joint variable of the model; expected one of " + io::JoinNames(model_.variable_names()) +
               " (entry ignored)");
      continue;
    }
    received_[{kind, variable}] = values[k];
  }
}

void CommandInput::ApplyTo(Simulation* simulation) {
  std::map<std::pair<Kind, int>, double> received;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    received.swap(received_);
  }
  for (const auto& [key, value] : received) {
    const auto& [kind, variable] = key;
    try {
      if (kind == Kind::kEffort) {
        simulation->SetEffort(variable, value);
      } else {
        simulation->SetSetpoint(variable, value, setpoint_time_constant_);
      }
    } catch (const ConfigError& error) {
      WarnOnce(std::string("~") + TopicOf(kind) + ": " + error.what() + " (entry ignored)");
    }
  }
}

void CommandInput::Discard() {
  std::lock_guard<std::mutex> lock(mutex_);
  received_.clear();
}

void CommandInput::WarnOnce(const std::string& text) {
  // a controller repeats a bad command at its own rate: one line says it
  std::lock_guard<std::mutex> lock(warned_mutex_);
  if (!warned_.insert(text).second) return;
  ROS_WARN_STREAM("flexmbd: " << text << " [logged once]");
}

}  // namespace ros
}  // namespace flexmbd
