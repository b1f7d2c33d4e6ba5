#pragma once
/// @file
/// The ROS node (docs/ros.md): runs one case from the parameter server, publishes every output sample, records
/// it to a bag and CSV, and serves ~pause, ~resume, ~step and ~reset.
///
/// Threads: the run loop (solver, conversion, pace, commands) runs in the caller of Run(); an
/// AsyncSampleWriter publishes and records the samples the loop releases; the services and subscriber
/// callbacks run in one spinner thread and reach the loop only through RunControl (services) and CommandInput
/// (the command topics).
///
/// @code
///   flexmbd::ros::SimulatorNode node(ros::NodeHandle(), ros::NodeHandle("~"));
///   return node.Run();
/// @endcode

#include <ros/ros.h>

#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flexmbd/common/exit_status.hpp"
#include "flexmbd/ros/async_sample_writer.hpp"
#include "flexmbd/ros/clock_ticks.hpp"
#include "flexmbd/ros/command_input.hpp"
#include "flexmbd/ros/node_case.hpp"
#include "flexmbd/ros/pacer.hpp"
#include "flexmbd/ros/run_control.hpp"
#include "flexmbd/ros/topic_publisher.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace ros {

class SimulatorNode {
 public:
  /// Loads the case and opens the outputs. Throws ConfigError (bad URDF, parameter or output path), or
  /// OutputError (an output file that cannot be written).
  SimulatorNode(::ros::NodeHandle node, ::ros::NodeHandle private_node);

  /// Runs the case until it ends (or, with ~keep_alive, until shutdown), or until SIGINT / SIGTERM. The
  /// recording files are closed on every way out and hold every sample computed, or after a failed write
  /// what they took. Returns kExitSuccess, or kExitRunFailed after a SolverError or an OutputError.
  int Run();

 private:
  using Clock = std::chrono::steady_clock;

  void StartRun();
  void Collect(const OutputSample& sample);
  void AdvanceOneChunk();
  void ServeCommand();
  std::optional<RunControl::Reply> Execute(RunControl::Command command);
  bool SubscribersReady();
  /// Samples or clock ticks computed and not yet sent.
  bool OutputPending() const;
  /// Sends the earlier of the next sample and the next clock tick once it is due.
  void SendNext();
  void FlushPending();
  void ReportEnd();
  void LetSubscribersDrain();
  void Wait(Clock::time_point until);
  /// The run has computed its end and sent every sample: ~step, ~pause and ~resume have nothing to act on.
  bool RunEnded() const;
  RunControl::Reply RunEndedReply() const;
  std::string LastSampleText() const;

  ::ros::NodeHandle node_, private_node_;
  NodeCase case_;
  Pacer pacer_;
  RunControl control_;
  std::unique_ptr<SampleFanOut> outputs_;
  TopicPublisher* publisher_ = nullptr;        ///< owned by outputs_; null when ~publish is false
  std::unique_ptr<AsyncSampleWriter> writer_;  ///< writes to outputs_
  std::vector<::ros::ServiceServer> services_;
  std::unique_ptr<CommandInput> commands_;     ///< ~effort_command, ~position_command

  // the current run
  std::unique_ptr<SampleConverter> converter_;
  std::unique_ptr<Simulation> simulation_;
  const Simulation::SampleSink collect_ = [this](const OutputSample& sample) { Collect(sample); };
  std::deque<AsyncSampleWriter::RecordPtr> pending_;  ///< computed, not yet sent: the solver may run ahead
                                                      ///< of the pace and of a pause
  std::optional<ClockTicks> clock_ticks_;  ///< reached, not yet sent; none without /clock
  std::optional<double> last_sent_t_;  ///< time of the last sample released to the writer [s]
  long samples_sent_ = 0;
  Clock::time_point first_sent_wall_;  ///< when the run's first sample was sent
  bool computed_to_end_ = false;       ///< the solver has reached t_end (samples may still be pending)
  bool reported_end_ = false;          ///< the end-of-run summary was logged

  // commands
  bool subscribers_ready_ = false;  ///< ~wait_for_subscribers was met once
  std::optional<Clock::time_point> wait_started_;  ///< when the wait for subscribers began
  std::string waiting_on_;  ///< the topics the wait for subscribers was last logged as missing
  bool paused_ = false;
  bool step_in_progress_ = false;  ///< a ~step waits for its sample to be sent
  bool anchor_pace_ = true;        ///< re-anchor the pace at the next sample (start, resume, reset)
};

}  // namespace ros
}  // namespace flexmbd
