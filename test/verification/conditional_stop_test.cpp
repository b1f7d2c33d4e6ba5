// Conditional stops (docs/theory.md, "Stops", retraction rule): a stop that retracts at the first separation
// after the rate of a named joint exceeds a threshold and engages again below a lower one, with the gap open.
// The named joint is a hub driven by a (1 - cos) ramp, so the threshold instants are known in closed form; the
// stop sits on a second joint, a flap, whose contacts are known in closed form too.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "case_builders.hpp"
#include "run_trace.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace conditional_stop_test {

// Hub drive: q(t) = (kHubTurn / 2) (1 - cos(pi t / kRampTime)), rate kPeakRate sin(pi t / kRampTime).
constexpr double kHubTurn = 2.0, kRampTime = 1.0;
const double kPeakRate = 0.5 * kHubTurn * M_PI / kRampTime;
// The thresholds are chosen by the instants at which the rate passes them (rising, then falling): mid-step of
// the fixed step kStep, so that the scheme's rate error of the driven joint, O(h^2 q''') ~ 3e-3 rad/s, stays
// far below the rate change over half a step (h/2 |q''| >= 0.015 rad/s here): the event is then at the end of
// the step that contains the instant.
constexpr double kStep = 0.01;
constexpr double kRetractTime = 0.215, kEngageTime = 0.885;
double RateAt(double t) { return kPeakRate * std::sin(M_PI * t / kRampTime); }

// Flap on its own revolute joint (about y at x = 1 m), centre of mass on the axis so gravity does no work
// on it, inertia kFlapInertia; a lower stop of radius kStopRadius at -kStopAngle.
constexpr double kFlapInertia = 0.2, kStopAngle = 0.25, kStopRadius = 0.1;

ModelSpec HubAndFlap(double t_end) {
  ModelSpec spec;
  spec.source = "hub and flap (test)";
  spec.bodies.push_back(test::ArmBody("hub", 1.0, 0.0, 0.1));
  BodySpec flap = test::ArmBody("flap", 1.0, 0.0, kFlapInertia);
  flap.p_WB = Vec3(1.0, 0, 0);
  spec.bodies.push_back(flap);
  JointSpec hub = test::RevoluteY("hub", "", "hub", Vec3::Zero());
  TimeFunctionSpec ramp;
  ramp.kind = TimeFunctionSpec::Kind::kCosineRamp;
  ramp.value = kHubTurn;
  ramp.duration = kRampTime;
  hub.effects[0].drives.push_back(ramp);
  spec.joints.push_back(hub);
  JointSpec hinge = test::RevoluteY("flap", "", "flap", Vec3(1.0, 0, 0));
  StopSpec stop = test::Stop(StopSpec::Side::kLower, -kStopAngle, kStopRadius);
  stop.retraction.joint = "hub";
  stop.retraction.retract_above = RateAt(kRetractTime);
  stop.retraction.engage_below = RateAt(kEngageTime);
  hinge.effects[0].stops.push_back(stop);
  spec.joints.push_back(hinge);
  spec.solver.gravity = Vec3(0, 0, -9.81);
  spec.solver.adaptive = false;
  spec.solver.dt = kStep;
  spec.solver.t_end = t_end;
  spec.solver.tol = 1.0e-12;
  spec.output.rate_hz = 0;  // a sample at every accepted step
  return spec;
}

// The flap turning toward its stop at a constant rate.
void SetFlapRate(double rate, ModelSpec* spec) {
  spec->joints[1].initial_velocity = {rate};
  spec->bodies[1].w_WB_W = Vec3(0, rate, 0);
}

// Time of the accepted step before the one that ended at t (steps are sampled one by one).
double StepStart(const test::Trace& run, double t) {
  double start = 0;
  for (const OutputSample& s : run.samples) {
    if (s.t < t) start = s.t;
  }
  return start;
}

// Time sums of fixed steps agree with the step ends to round-off.
constexpr double kTimeRoundOff = 1.0e-12;

void ExpectEventInStep(const test::Trace& run, const EffectEvent& event, double instant, int from, int to) {
  EXPECT_EQ(event.from, from);
  EXPECT_EQ(event.to, to);
  EXPECT_GT(event.t, instant) << "the event precedes its instant";
  EXPECT_LT(StepStart(run, event.t), instant + kTimeRoundOff) << "the event is later than the step of its instant";
}

TEST(ConditionalStop, OpenStopRetractsAtTheThresholdAndEngagesBelowTheLowerOne) {
  // The flap rests away from its stop: the gap stays open, so the rule acts at the threshold instants.
  const test::Trace run = test::RunTrace(HubAndFlap(1.0));
  ASSERT_EQ(run.events.size(), 2u);
  ExpectEventInStep(run, run.events[0], kRetractTime, JointStop::kOpen, JointStop::kRetracted);
  ExpectEventInStep(run, run.events[1], kEngageTime, JointStop::kRetracted, JointStop::kOpen);
}

TEST(ConditionalStop, RetractedStopExertsNoForceAndStaysRetractedWhileClosed) {
  // The flap turns toward its stop at 0.5 rad/s and would reach it at 0.5 s, after the retraction (0.22 s).
  constexpr double kFlapRate = -0.5;
  ModelSpec spec = HubAndFlap(1.0);
  SetFlapRate(kFlapRate, &spec);
  const test::Trace run = test::RunTrace(spec);
  // One event: at 0.885 s the hub is slow again but the flap is beyond the stop, so it does not engage.
  ASSERT_EQ(run.events.size(), 1u);
  ExpectEventInStep(run, run.events[0], kRetractTime, JointStop::kOpen, JointStop::kRetracted);
  // No force on the flap: its rate and travel are those of free rotation, to the Newton tolerance (1e-12)
  // accumulated over 100 steps.
  constexpr double kFreeMotionTolerance = 1.0e-9;
  for (const OutputSample& s : run.samples) {
    EXPECT_FALSE(s.stops[0].in_contact) << "t = " << s.t;
    EXPECT_EQ(s.stops[0].force, 0.0) << "t = " << s.t;
    EXPECT_NEAR(s.velocity[1], kFlapRate, kFreeMotionTolerance) << "t = " << s.t;
  }
  EXPECT_NEAR(run.samples.back().position[1], kFlapRate * run.samples.back().t, kFreeMotionTolerance);
  EXPECT_LT(run.samples.back().position[1], -kStopAngle);

  // The same flap without the rule bounces off the stop.
  spec.joints[1].effects[0].stops[0].retraction = {};
  const test::Trace control = test::RunTrace(spec);
  ASSERT_EQ(control.events.size(), 2u);
  EXPECT_GT(control.samples.back().velocity[1], 0.0);
}

TEST(ConditionalStop, StopInContactRetractsAtTheSeparation) {
  // The flap is now a pendulum (1 kg, centre of mass 0.5 m out) resting on its stop at the horizontal, held by
  // gravity, while a moment rising linearly in time lifts it: the contact force m g a / rho - M(t) / rho turns
  // to a pull at t_sep = m g a / kMomentRate. The hub passes the retraction threshold at 0.215 s while the flap
  // is still in contact, so the stop retracts at the separation, in the step containing t_sep (chosen a quarter
  // into a step, so that the load, whether taken at the step's end or its middle, pulls within that step).
  constexpr double kMassKg = 1.0, kArm = 0.5, kG = 9.81, kSeparationTime = 0.4025;
  const double moment_rate = kMassKg * kG * kArm / kSeparationTime;  // [N m/s]
  ModelSpec spec = HubAndFlap(1.0);
  spec.bodies[1] = test::ArmBody("flap", kMassKg, kArm, 0.01);
  spec.bodies[1].p_WB = Vec3(1.0, 0, 0);
  // Gravity turns the flap toward positive angles (a turn about y takes its arm from +x down toward -z): an
  // upper stop at 0 holds it horizontal, and the lifting moment is negative about y.
  StopSpec& stop = spec.joints[1].effects[0].stops[0];
  stop.side = StopSpec::Side::kUpper;
  stop.limit = 0.0;
  stop.name = "upper";
  LoadSpec lift;
  lift.body = "flap";
  lift.kind = LoadSpec::Kind::kMoment;
  lift.vector = Vec3(0, -moment_rate, 0);
  lift.scale.kind = TimeFunctionSpec::Kind::kLinearRamp;
  lift.scale.value = 1.0;
  lift.scale.duration = 1.0;
  spec.loads.push_back(lift);
  const test::Trace run = test::RunTrace(spec);
  // Contact from the first step, retraction at the separation, engagement below the lower threshold.
  ASSERT_EQ(run.events.size(), 3u);
  EXPECT_EQ(run.events[0].to, JointStop::kContact);
  EXPECT_NEAR(run.events[0].t, 0.0, kTimeRoundOff);  // the first step is solved in contact: from its start
  ExpectEventInStep(run, run.events[1], kSeparationTime, JointStop::kContact, JointStop::kRetracted);
  ExpectEventInStep(run, run.events[2], kEngageTime, JointStop::kRetracted, JointStop::kOpen);
  for (const OutputSample& s : run.samples) {
    if (s.t > run.events[1].t) {
      EXPECT_EQ(s.stops[0].force, 0.0) << "t = " << s.t;
    }
  }
}

}  // namespace conditional_stop_test
}  // namespace flexmbd
