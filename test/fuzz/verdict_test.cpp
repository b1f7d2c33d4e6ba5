// The fuzzer's oracle (harness/verdict.hpp): which outcomes are findings.

#include <gtest/gtest.h>

#include <csignal>

#include "harness/verdict.hpp"

namespace flexmbd {
namespace fuzz {
namespace verdict_test {

IsolatedResult Returned(Outcome outcome, const std::string& message) {
  IsolatedResult isolated;
  isolated.result = TargetResult{outcome, message};
  return isolated;
}

TEST(Verdict, OneLineConfigErrorNamingTheFileIsAccepted) {
  EXPECT_EQ(Judge(Returned(Outcome::kConfigError, "fuzz_case.yaml: solver.dt: -1 is negative")).finding,
            Finding::kNone);
}

TEST(Verdict, ConfigErrorNamingNoFileIsABadMessage) {
  EXPECT_EQ(Judge(Returned(Outcome::kConfigError, "solver.dt: -1 is negative")).finding,
            Finding::kBadMessage);
}

TEST(Verdict, ConfigErrorNamingTheParametersIsAccepted) {
  EXPECT_EQ(Judge(Returned(Outcome::kConfigError, "/flexmbd_node/solver/dt: a date")).finding, Finding::kNone);
}

TEST(Verdict, MessageOfTwoLinesIsABadMessage) {
  EXPECT_EQ(Judge(Returned(Outcome::kSolverError, "t = 0.1 s:\nstep below dt_min")).finding,
            Finding::kBadMessage);
}

TEST(Verdict, OtherExceptionIsAFinding) {
  EXPECT_EQ(Judge(Returned(Outcome::kOtherException, "std::out_of_range: vector")).finding,
            Finding::kWrongException);
}

TEST(Verdict, CrashAndHangAreFindings) {
  IsolatedResult crashed;
  crashed.termination = Termination::kCrashed;
  crashed.signal = SIGSEGV;
  EXPECT_EQ(Judge(crashed).finding, Finding::kCrash);
  IsolatedResult timed_out;
  timed_out.termination = Termination::kTimedOut;
  EXPECT_EQ(Judge(timed_out).finding, Finding::kHang);
}

}  // namespace verdict_test
}  // namespace fuzz
}  // namespace flexmbd
