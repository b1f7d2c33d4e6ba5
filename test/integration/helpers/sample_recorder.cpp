#include "sample_recorder.hpp"

namespace flexmbd {
namespace test {
namespace {
// Large enough for every sample of a test run: a burst at real_time_factor 0 must not drop any.
constexpr uint32_t kQueueSize = 100000;
// Stamps are nanoseconds.
constexpr double kStampResolution = 1.0e-9;

template <typename Message>
bool Reached(const std::vector<Message>& messages, double t) {
  return !messages.empty() && TimeOf(messages.back()) >= t - kStampResolution;
}
}  // namespace

template <typename Message>
::ros::Subscriber SampleRecorder::Subscribe(const std::string& topic, std::vector<Message> Samples::*field) {
  ::ros::SubscribeOptions options = ::ros::SubscribeOptions::create<Message>(
      topic, kQueueSize,
      [this, field](const typename Message::ConstPtr& message) {
        std::lock_guard<std::mutex> lock(mutex_);
        (samples_.*field).push_back(*message);
        arrived_.notify_all();
      },
      ::ros::VoidPtr(), &queue_);
  options.transport_hints = ::ros::TransportHints().tcpNoDelay();
  return handle_.subscribe(options);
}

SampleRecorder::SampleRecorder(const std::string& node_name) : spinner_(1, &queue_) {
  const std::string prefix = "/" + node_name + "/";
  subscribers_.push_back(Subscribe("/joint_states", &Samples::joint_states));
  subscribers_.push_back(Subscribe(prefix + "energy", &Samples::energy));
  subscribers_.push_back(Subscribe(prefix + "reactions", &Samples::reactions));
  subscribers_.push_back(Subscribe(prefix + "solver", &Samples::solver));
  subscribers_.push_back(Subscribe("/tf", &Samples::transforms));
  subscribers_.push_back(Subscribe(prefix + "contacts", &Samples::contacts));
  subscribers_.push_back(Subscribe(prefix + "friction", &Samples::friction));
  subscribers_.push_back(Subscribe(prefix + "beam_loads", &Samples::beam_loads));
  subscribers_.push_back(Subscribe(prefix + "aero_loads", &Samples::aero_loads));
  spinner_.start();
}

SampleRecorder::~SampleRecorder() {
  spinner_.stop();
  for (::ros::Subscriber& subscriber : subscribers_) subscriber.shutdown();
}

bool SampleRecorder::WaitUntil(const std::function<bool(const Samples&)>& done, std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  return arrived_.wait_for(lock, timeout, [&] { return done(samples_); });
}

bool EverySampleTopicReached(const Samples& s, double t) {
  return Reached(s.joint_states, t) && Reached(s.energy, t) && Reached(s.reactions, t) && Reached(s.solver, t);
}

bool SampleRecorder::WaitForTime(double t, std::chrono::milliseconds timeout) {
  return WaitUntil([t](const Samples& s) { return EverySampleTopicReached(s, t); }, timeout);
}

Samples SampleRecorder::Snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return samples_;
}

}  // namespace test
}  // namespace flexmbd
