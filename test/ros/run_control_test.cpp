// RunControl (include/flexmbd/ros/run_control.hpp): a service request returns once the loop has answered.

#include "flexmbd/ros/run_control.hpp"

#include <gtest/gtest.h>

#include <future>
#include <thread>

namespace flexmbd {
namespace ros {
namespace run_control_test {

using Command = RunControl::Command;
// Generous bound on thread hand-offs on a loaded machine; the tests never wait for it when they pass.
constexpr std::chrono::seconds kHandOff(10);

TEST(RunControl, RequestReturnsTheLoopsAnswer) {
  RunControl control;
  std::future<RunControl::Reply> reply =
      std::async(std::launch::async, [&] { return control.Request(Command::kStep); });
  std::optional<Command> taken;
  while (!(taken = control.Take())) control.WaitUntil(RunControl::Clock::now() + kHandOff);
  EXPECT_EQ(*taken, Command::kStep);
  EXPECT_EQ(reply.wait_for(std::chrono::milliseconds(50)), std::future_status::timeout) << "answered before the loop";
  control.Answer({true, "sent the sample at t = 0.5 s"});
  const RunControl::Reply answer = reply.get();
  EXPECT_TRUE(answer.success);
  EXPECT_EQ(answer.message, "sent the sample at t = 0.5 s");
}

TEST(RunControl, CloseReleasesAWaitingRequestWithFailure) {
  RunControl control;
  std::future<RunControl::Reply> reply =
      std::async(std::launch::async, [&] { return control.Request(Command::kPause); });
  while (!control.Take()) control.WaitUntil(RunControl::Clock::now() + kHandOff);
  control.Close();
  EXPECT_FALSE(reply.get().success);
  EXPECT_FALSE(control.Request(Command::kResume).success);
}

TEST(RunControl, NotifyWakesTheLoop) {
  RunControl control;
  std::thread notifier([&] { control.Notify(); });
  const auto start = RunControl::Clock::now();
  control.WaitUntil(start + kHandOff);
  EXPECT_LT(RunControl::Clock::now() - start, kHandOff);
  notifier.join();
}

}  // namespace run_control_test
}  // namespace ros
}  // namespace flexmbd
