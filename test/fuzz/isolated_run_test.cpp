// The fuzzer's isolation (harness/isolated_run.hpp): how a child ends is told apart exactly.

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>

#include "flexmbd/common/error.hpp"
#include "harness/isolated_run.hpp"

namespace flexmbd {
namespace fuzz {
namespace isolated_run_test {

IsolationLimits OneSecond() {
  IsolationLimits limits;
  limits.seconds = 1;
  return limits;
}

TEST(IsolatedRun, ReturnedResultCrossesToTheParent) {
  const IsolatedResult isolated =
      RunIsolated([] { return TargetResult{Outcome::kConfigError, "a.yaml: solver.dt: -1"}; }, OneSecond());
  EXPECT_EQ(isolated.termination, Termination::kReturned);
  EXPECT_EQ(isolated.result.outcome, Outcome::kConfigError);
  EXPECT_EQ(isolated.result.message, "a.yaml: solver.dt: -1");
}

TEST(IsolatedRun, SegfaultIsACrash) {
  const IsolatedResult isolated = RunIsolated(
      [] {
        raise(SIGSEGV);
        return TargetResult{};
      },
      OneSecond());
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer catches the signal, prints its report and exits with status 1
  EXPECT_EQ(isolated.termination, Termination::kExited);
  EXPECT_EQ(isolated.exit_code, 1);
#else
  EXPECT_EQ(isolated.termination, Termination::kCrashed);
  EXPECT_EQ(isolated.signal, SIGSEGV);
#endif
}

TEST(IsolatedRun, FailedInternalCheckIsACrash) {
  const IsolatedResult isolated = RunIsolated(
      [] {
        FLEXMBD_DEMAND(getpid() == 0);
        return TargetResult{};
      },
      OneSecond());
  EXPECT_EQ(isolated.termination, Termination::kCrashed);
  EXPECT_EQ(isolated.signal, SIGABRT);
}

TEST(IsolatedRun, EndlessLoopIsAHang) {
  const IsolatedResult isolated = RunIsolated(
      [] {
        for (volatile bool forever = true; forever;) {
        }
        return TargetResult{};
      },
      OneSecond());
  EXPECT_EQ(isolated.termination, Termination::kTimedOut);
}

// The limit is CPU time: a child that waits (as one at low priority on a busy machine does) is not a hang. Before,
// a wall-clock limit reported the antenna with friction, 0.3 s alone, as a hang in a campaign at nice 19 beside
// two builds.
TEST(IsolatedRun, WaitingIsNotAHang) {
  const IsolatedResult isolated = RunIsolated(
      [] {
        sleep(2);
        return TargetResult{};
      },
      OneSecond());
  EXPECT_EQ(isolated.termination, Termination::kReturned);
}

TEST(IsolatedRun, ExitWithoutResultIsReported) {
  const IsolatedResult isolated = RunIsolated(
      [] {
        _exit(3);
        return TargetResult{};
      },
      OneSecond());
  EXPECT_EQ(isolated.termination, Termination::kExited);
  EXPECT_EQ(isolated.exit_code, 3);
}

}  // namespace isolated_run_test
}  // namespace fuzz
}  // namespace flexmbd
