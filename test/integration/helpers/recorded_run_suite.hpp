#pragma once
// The fixture of a rostest whose tests share one recorded run of the node and of the runner (RecordNodeAndRunner),
// made before the suite's first test; each test first checks that the run reached its end.

#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "node_run.hpp"

namespace flexmbd {
namespace test {

/// `Suite`, the fixture deriving from this, names its run with `static NodeRunCase Case()` and what the run is
/// awaited on (a topic, for the failure message) with `static constexpr char kAwaited[]`.
template <typename Suite>
class RecordedRunSuite : public testing::Test {
 protected:
  static void SetUpTestSuite() { record_ = new NodeRun(RecordNodeAndRunner(Suite::Case())); }
  static void TearDownTestSuite() {
    delete record_;
    record_ = nullptr;
  }
  void SetUp() override {
    ASSERT_TRUE(record_->reached_end) << Suite::kAwaited << " did not reach the run's end; node output:\n"
                                      << record_->node_output;
  }
  static inline NodeRun* record_ = nullptr;
};

/// The end condition of a run awaited on one topic: its last message is at `end_time` [s].
template <typename Message>
std::function<bool(const Samples&)> ReachesEnd(std::vector<Message> Samples::*topic, double end_time) {
  return [topic, end_time](const Samples& samples) {
    const std::vector<Message>& messages = samples.*topic;
    return !messages.empty() && TimeOf(messages.back()) >= end_time - 1e-9;
  };
}

}  // namespace test
}  // namespace flexmbd
