#include "flexmbd/ros/simulator_node.hpp"

#include <std_srvs/Trigger.h>

#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/message_text.hpp"
#include "flexmbd/ros/stop_signal.hpp"

namespace flexmbd {
namespace ros {
namespace {

// While it waits (pause, pace, subscribers), the loop checks ros::ok() (SIGINT, SIGTERM, rosnode kill) at
// least this often.
constexpr std::chrono::milliseconds kPollPeriod(20);
// roscpp drops the messages it has queued for a subscriber when the node shuts down, and cannot say when
// the queues are empty: at the end of a run the node stays this long for its subscribers to take them. A
// subscriber of every sample topic on the same 2-core VM takes 20000-30000 samples/s, so the most roscpp
// and the subscriber queue (10000 messages a topic each, plus the socket buffers) takes up to about 1 s
// (bench/node/README.md); 0.5 s cut the tail off half of the 20001-sample runs there.
constexpr std::chrono::milliseconds kDrainTime(1500);
// Samples handed to the writer thread together (one lock, at most one wake-up) when the run goes as fast as
// it can; paced runs hand over every sample at once.
constexpr size_t kUnpacedWakeBatch = 256;

std::string FormatTime(double t) {
  std::ostringstream text;
  text << std::setprecision(std::numeric_limits<double>::max_digits10) << t;
  return text.str();
}

}  // namespace

SimulatorNode::SimulatorNode(::ros::NodeHandle node, ::ros::NodeHandle private_node)
    : node_(std::move(node)),
      private_node_(std::move(private_node)),
      case_(LoadNodeCase(node_, private_node_)),
      pacer_(case_.settings.real_time_factor) {
  const tf2_msgs::TFMessage static_transforms = ToStaticTransforms(case_.frames.fixed);
  outputs_ = std::make_unique<SampleFanOut>(case_.model, case_.files, ResolveTopicNames(node_, private_node_),
                                            static_transforms);
  if (case_.settings.publish) {
    bool use_sim_time = false;
    ::ros::param::get("/use_sim_time", use_sim_time);
    auto publisher = std::make_unique<TopicPublisher>(node_, private_node_, case_.model, static_transforms,
                                                      use_sim_time, [this] { control_.Notify(); });
    publisher_ = publisher.get();
    private_node_.setParam(kRecordedTopicsParam, publisher->RecordedTopics());
    outputs_->AddLiveSink(std::move(publisher));
    if (use_sim_time) clock_ticks_.emplace(case_.settings.clock_rate_hz);
  }
  paused_ = case_.settings.paused;
  writer_ = std::make_unique<AsyncSampleWriter>(outputs_.get(),
                                                case_.settings.real_time_factor > 0.0 ? 1 : kUnpacedWakeBatch);
  const std::pair<const char*, RunControl::Command> services[] = {{"pause", RunControl::Command::kPause},
                                                                  {"resume", RunControl::Command::kResume},
                                                                  {"step", RunControl::Command::kStep},
                                                                  {"reset", RunControl::Command::kReset}};
  commands_ = std::make_unique<CommandInput>(private_node_, case_.model, case_.settings.setpoint_time_constant);
  for (const auto& [name, command] : services) {
    const RunControl::Command posted = command;
    services_.push_back(private_node_.advertiseService<std_srvs::Trigger::Request, std_srvs::Trigger::Response>(
        name, [this, posted](std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
          const RunControl::Reply reply = control_.Request(posted);
          response.success = reply.success;
          response.message = reply.message;
          return true;
        }));
  }
}

int SimulatorNode::Run() {
  ::ros::AsyncSpinner spinner(1);  // services and connection callbacks, beside the run loop
  spinner.start();
  const SolverSpec& solver = case_.model.solver();
  ROS_INFO_STREAM("flexmbd: " << case_.model.source() << ": " << case_.model.bodies().size() << " bodies, "
                              << case_.model.num_variables() << " joint variables, t_end = " << solver.t_end << " s, "
                              << case_.model.output().rate_hz << " samples/s (0: every step), "
                              << "real_time_factor " << case_.settings.real_time_factor
                              << (case_.files.bag.empty() ? "" : ", bag " + case_.files.bag));
  int status = kExitSuccess;
  try {
    StartRun();
    while (::ros::ok() && !StopRequested()) {
      if (computed_to_end_ && !OutputPending()) ReportEnd();  // first, so that no command sees open files
      ServeCommand();
      if (paused_ && !step_in_progress_) {
        Wait(Clock::now() + kPollPeriod);
      } else if (OutputPending()) {
        SendNext();
      } else if (!computed_to_end_) {
        AdvanceOneChunk();
      } else if (case_.settings.keep_alive) {
        Wait(Clock::now() + kPollPeriod);
      } else {
        break;
      }
    }
    if (computed_to_end_ && !OutputPending()) LetSubscribersDrain();
  } catch (const SolverError& error) {
    ROS_FATAL_STREAM("flexmbd: run failed: " << error.what());
    ROS_INFO_STREAM("flexmbd: " << simulation_->statistics().Summary(simulation_->model()));
    status = kExitRunFailed;
    FlushPending();  // may throw OutputError, which main reports
  } catch (const OutputError& error) {  // the recording files are closed (SampleFanOut::Write)
    ROS_FATAL_STREAM("flexmbd: " << error.what());
    status = kExitRunFailed;
  }
  if (StopRequested() || !::ros::ok()) {
    FlushPending();  // record what was computed
    ROS_INFO_STREAM("flexmbd: stopped at t = " << simulation_->state().t << " s after " << samples_sent_
                                               << " samples sent");
  }
  control_.Close();
  writer_->Flush();
  outputs_->Close();
  spinner.stop();
  return status;
}

void SimulatorNode::StartRun() {
  if (simulation_) {  // a reset: the files restart with the run
    writer_->Flush();
    outputs_->RestartRecordings();
  }
  pending_.clear();
  last_sent_t_.reset();
  samples_sent_ = 0;
  computed_to_end_ = false;
  reported_end_ = false;
  anchor_pace_ = true;
  converter_ = std::make_unique<SampleConverter>(case_.model, case_.frames);
  simulation_ = std::make_unique<Simulation>(case_.model);
  if (clock_ticks_) clock_ticks_->Restart(simulation_->state().t);
  const SolverSpec& solver = case_.model.solver();
  if (solver.analysis == SolverSpec::Analysis::kStatic) {
    simulation_->Run(collect_);
    computed_to_end_ = true;
    return;
  }
  if (solver.static_first) simulation_->SolveStaticStart();
  simulation_->Begin(collect_);
}

void SimulatorNode::Collect(const OutputSample& sample) {
  AsyncSampleWriter::RecordPtr record = writer_->Acquire();
  record->sample = sample;  // into the recycled record's storage
  converter_->Convert(sample, simulation_->state(), &record->messages);
  pending_.push_back(std::move(record));
  if (clock_ticks_) clock_ticks_->Reached(sample.t);
}

void SimulatorNode::AdvanceOneChunk() {
  // About one step per chunk (the size of the last one; dt at first), so that commands, the pace and
  // shutdown are served between steps. The core never cuts a step to land on `until`, so chunking does not
  // change the results.
  const SolverSpec& solver = case_.model.solver();
  const State& state = simulation_->state();
  const double chunk = state.h_prev > 0.0 ? state.h_prev : solver.dt;
  const double until = std::min(state.t + chunk, solver.t_end);
  commands_->ApplyTo(simulation_.get());  // from the next step on
  simulation_->AdvanceTo(until, solver.t_end, collect_);
  if (clock_ticks_) clock_ticks_->Reached(simulation_->state().t);
  computed_to_end_ = until >= solver.t_end;
}

void SimulatorNode::ServeCommand() {
  const std::optional<RunControl::Command> command = control_.Take();
  if (!command) return;
  if (std::optional<RunControl::Reply> reply = Execute(*command)) control_.Answer(std::move(*reply));
}

std::optional<RunControl::Reply> SimulatorNode::Execute(RunControl::Command command) {
  switch (command) {
    case RunControl::Command::kPause:
      if (RunEnded()) return RunEndedReply();
      paused_ = true;
      writer_->Flush();  // the reply names the last sample published
      return RunControl::Reply{true, "paused after " + LastSampleText()};
    case RunControl::Command::kResume:
      if (RunEnded()) return RunEndedReply();
      paused_ = false;
      anchor_pace_ = true;
      return RunControl::Reply{true, "resumed after " + LastSampleText()};
    case RunControl::Command::kStep:
      if (RunEnded()) return RunEndedReply();
      paused_ = true;
      step_in_progress_ = true;
      return std::nullopt;  // answered when the sample is sent
    case RunControl::Command::kReset:
      commands_->Discard();  // the new run starts without commands
      StartRun();
      return RunControl::Reply{
          true, "reset to the initial state; the next sample is at t = " + FormatTime(simulation_->state().t) + " s"};
  }
  return std::nullopt;
}

bool SimulatorNode::SubscribersReady() {
  const NodeSettings& settings = case_.settings;
  subscribers_ready_ =
      subscribers_ready_ || !publisher_ || publisher_->MinSampleSubscribers() >= settings.wait_for_subscribers;
  if (subscribers_ready_) return true;
  const Clock::time_point now = Clock::now();
  if (!wait_started_) wait_started_ = now;
  // Said whenever the topics still missing change, not once: the line written before a recorder connected named
  // every topic, and stayed the only word of a recorder that never took one of them (explore23 ros/record_hang).
  const std::string topics = io::JoinNames(publisher_->SampleTopicsBelow(settings.wait_for_subscribers));
  if (topics != waiting_on_) {
    ROS_INFO("flexmbd: waiting for %d subscriber(s) on each sample topic (~wait_for_subscribers) before the "
             "first sample; still missing on: %s",
             settings.wait_for_subscribers, topics.c_str());
    waiting_on_ = topics;
  }
  if (std::chrono::duration<double>(now - *wait_started_).count() > settings.wait_for_subscribers_timeout) {
    std::ostringstream msg;
    msg << "~wait_for_subscribers: still no subscriber on " << topics << " after "
        << settings.wait_for_subscribers_timeout << " s (~wait_for_subscribers_timeout); expected "
        << settings.wait_for_subscribers << " on every sample topic (a recorder of the topics in ~"
        << kRecordedTopicsParam << ")";
    throw OutputError(msg.str());
  }
  return false;
}

bool SimulatorNode::OutputPending() const { return !pending_.empty() || (clock_ticks_ && !clock_ticks_->empty()); }

void SimulatorNode::SendNext() {
  if (!SubscribersReady()) {
    Wait(Clock::now() + kPollPeriod);
    return;
  }
  // a tick at a sample's time goes first: /clock reaches t as the sample stamped t goes out
  const bool tick_next = clock_ticks_ && !clock_ticks_->empty() &&
                         (pending_.empty() || clock_ticks_->front() <= pending_.front()->sample.t);
  const double t = tick_next ? clock_ticks_->front() : pending_.front()->sample.t;
  const Clock::time_point now = Clock::now();
  if (anchor_pace_) {
    pacer_.Anchor(t, now);
    anchor_pace_ = false;
  }
  const Clock::time_point due = step_in_progress_ ? now : pacer_.Due(t);
  if (now < due) {
    Wait(due);
    return;
  }
  if (tick_next) {
    publisher_->PublishClock(t);
    clock_ticks_->pop();
    return;
  }
  writer_->Submit(std::move(pending_.front()));
  pending_.pop_front();
  if (samples_sent_++ == 0) first_sent_wall_ = now;
  last_sent_t_ = t;
  if (step_in_progress_) {
    step_in_progress_ = false;
    writer_->Flush();  // the reply comes once the sample is published
    control_.Answer(RunControl::Reply{true, "sent " + LastSampleText()});
  }
}

void SimulatorNode::FlushPending() {
  for (AsyncSampleWriter::RecordPtr& next : pending_) writer_->Submit(std::move(next));
  pending_.clear();
  writer_->Flush();
}

void SimulatorNode::ReportEnd() {
  if (step_in_progress_) {  // the last chunk ended the run without a sample for the step
    step_in_progress_ = false;
    control_.Answer(RunEndedReply());
  }
  if (reported_end_) return;
  reported_end_ = true;
  writer_->Flush();
  outputs_->CloseRecordings();  // the files are complete: readable while the node stays up
  const std::chrono::duration<double> wall = Clock::now() - first_sent_wall_;
  ROS_INFO_STREAM("flexmbd: finished at t = " << simulation_->state().t << " s; " << samples_sent_
                                              << " samples sent in " << wall.count() << " s wall time");
  ROS_INFO_STREAM("flexmbd: " << simulation_->statistics().Summary(simulation_->model()));
  for (const std::string& line :
       DescribeEffectIntervals(simulation_->model(), simulation_->effect_events(), simulation_->state())) {
    ROS_INFO_STREAM("flexmbd: " << line);
  }
}

void SimulatorNode::LetSubscribersDrain() {
  if (!publisher_ || !publisher_->HasSubscribers()) return;
  const Clock::time_point until = Clock::now() + kDrainTime;
  while (Clock::now() < until && ::ros::ok() && !StopRequested()) Wait(until);
}

void SimulatorNode::Wait(Clock::time_point until) {
  writer_->Wake();  // what was released is written while the loop waits
  control_.WaitUntil(std::min(until, Clock::now() + kPollPeriod));
}

bool SimulatorNode::RunEnded() const { return computed_to_end_ && pending_.empty(); }

RunControl::Reply SimulatorNode::RunEndedReply() const {
  return RunControl::Reply{false, "the run has ended after " + LastSampleText() + "; call ~reset to start over"};
}

std::string SimulatorNode::LastSampleText() const {
  return last_sent_t_ ? "the sample at t = " + FormatTime(*last_sent_t_) + " s" : "no sample yet";
}

}  // namespace ros
}  // namespace flexmbd
