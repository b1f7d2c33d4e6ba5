// The runner's report of contact intervals (DescribeEffectIntervals, src/core/solver/effect_events.cpp): one
// line per stop from the mode changes of a run. Reference: the intervals written by hand from the events below.

#include <gtest/gtest.h>

#include <vector>

#include "flexmbd/solver/effect_events.hpp"
#include "tangent_test_models.hpp"

namespace flexmbd {
namespace effect_events_test {

TEST(EffectEvents, ContactIntervalsPerStopCloseAtTheEndOfTheRun) {
  ModelSpec spec = test::WorldRevoluteModel();  // hinge at 0.3 rad
  StopSpec lower, upper;
  lower.name = "lower";
  lower.side = StopSpec::Side::kLower;
  lower.limit = 0.25;
  upper.name = "upper";
  upper.side = StopSpec::Side::kUpper;
  upper.limit = 0.5;
  spec.joints[0].effects[0].stops = {lower, upper};
  const Model model = BuildModel(spec);
  // Lower: a contact from 0.5 to 0.52 s, one from 0.6 s ended by a retraction at 0.7 s, and one from 0.93 s
  // still on at the end (1 s). Upper: none (it retracts and engages again without contact).
  const std::vector<EffectEvent> events = {
      {0.5, 0, JointStop::kOpen, JointStop::kContact},    {0.52, 0, JointStop::kContact, JointStop::kOpen},
      {0.6, 0, JointStop::kOpen, JointStop::kContact},    {0.65, 1, JointStop::kOpen, JointStop::kRetracted},
      {0.7, 0, JointStop::kContact, JointStop::kRetracted}, {0.8, 0, JointStop::kRetracted, JointStop::kOpen},
      {0.85, 1, JointStop::kRetracted, JointStop::kOpen}, {0.93, 0, JointStop::kOpen, JointStop::kContact}};
  State end = model.initial_state();
  end.t = 1.0;
  EXPECT_EQ(DescribeEffectIntervals(model, events, end),
            (std::vector<std::string>{"stop hinge lower: 3 contact interval(s) [0.5, 0.52] [0.6, 0.7] [0.93, 1] s",
                                      "stop hinge upper: 0 contact interval(s)"}));
}

// A friction that sticks at the end of a step and breaks away from the start of the next has two events at one instant:
// a momentary stop, counted but not listed as an interval [t, t] (it had printed "[0, 0]" and "[2.00735, 2.00735]").
TEST(EffectEvents, ZeroLengthIntervalsAreCountedNotListed) {
  ModelSpec spec = test::WorldRevoluteModel();
  StopSpec lower;
  lower.name = "lower";
  lower.side = StopSpec::Side::kLower;
  lower.limit = 0.25;
  spec.joints[0].effects[0].stops = {lower};
  const Model model = BuildModel(spec);
  const std::vector<EffectEvent> events = {
      {0.2, 0, JointStop::kOpen, JointStop::kContact}, {0.2, 0, JointStop::kContact, JointStop::kOpen},
      {0.5, 0, JointStop::kOpen, JointStop::kContact}, {0.6, 0, JointStop::kContact, JointStop::kOpen}};
  State end = model.initial_state();
  end.t = 1.0;
  EXPECT_EQ(DescribeEffectIntervals(model, events, end),
            (std::vector<std::string>{"stop hinge lower: 1 contact interval(s) [0.5, 0.6] s and 1 of zero length"}));
}

}  // namespace effect_events_test
}  // namespace flexmbd
