// Coulomb friction in joints (docs/theory.md, "Friction"): spin-down, breakaway, the stick-slip oscillator,
// the regularised law's limit and the normal force from the joint reaction, against closed forms.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "case_builders.hpp"
#include "friction_bound.hpp"
#include "landing_run.hpp"
#include "run_trace.hpp"
#include "flexmbd/common/error.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace friction_test {

// Rotor J = 0.5 kg m^2 on a frictional revolute joint, no gravity: the normal force is the preload alone.
constexpr double kInertia = 0.5, kRadius = 0.02, kPreload = 100.0, kMuS = 0.3, kMuK = 0.2;
constexpr double kKineticTorque = kMuK * kRadius * kPreload;  // 0.4 N m
constexpr double kStaticTorque = kMuS * kRadius * kPreload;   // 0.6 N m

FrictionSpec Friction(double mu_s, double mu_k, double v0) {
  FrictionSpec f;
  f.mu_s = mu_s;
  f.mu_k = mu_k;
  f.radius = kRadius;
  f.preload = kPreload;
  f.v0 = v0;
  return f;
}

ModelSpec FrictionalRotor(double omega0, const FrictionSpec& friction, double t_end) {
  ModelSpec spec = test::Rotor(kInertia, omega0, t_end);
  spec.solver.gravity = Vec3::Zero();
  spec.solver.dt_max = 0.05;
  spec.output.rate_hz = 0;
  spec.joints[0].effects[0].frictions = {friction};
  return spec;
}

double FirstStickTime(const test::Trace& run) {
  for (const EffectEvent& e : run.events) {
    if (e.to == FrictionEffect::kSticking) return e.t;
  }
  return -1;
}

TEST(Friction, SpinDownStopsAtAnalyticTimeAndStaysStuck) {
  constexpr double kOmega0 = 10.0, kV0 = 1.0e-4;
  const ModelSpec spec = FrictionalRotor(kOmega0, Friction(kMuS, kMuK, kV0), 15.0);
  const test::Trace run = test::RunTrace(spec);
  const Model model = BuildModel(spec);
  const double t_star = kInertia * kOmega0 / kKineticTorque;  // 12.5 s
  // Sticking begins once the slip speed is below v0, at most v0 / (rho * deceleration) = 6e-3 s before t*;
  // 1e-3 t* (the issue asks for 1%) bounds it.
  constexpr double kStopTimeTolerance = 1.0e-3;
  EXPECT_NEAR(FirstStickTime(run), t_star, kStopTimeTolerance * t_star);
  const double e0 = run.samples.front().total();
  for (const OutputSample& s : run.samples) {
    // The energy-preserving scheme and the friction's work over each step close the books to the Newton
    // tolerance (1e-12) over ~1000 steps: 1e-9 relative.
    constexpr double kEnergyTolerance = 1.0e-9;
    EXPECT_NEAR(s.total() + s.friction[0].work, e0, kEnergyTolerance * e0) << "t = " << s.t;
    EXPECT_LE(test::StaticBoundRatio(spec, model, s), 1.0 + 1e-9) << "t = " << s.t;  // (F3)
    if (s.t > t_star + 1e-9) {
      EXPECT_TRUE(s.friction[0].sticking) << "t = " << s.t;
      // The sticking step ends at rest up to the round-off of its increment of q (Newton stops at the noise
      // floor RoundOffFloor(|q|), q ~ 60 rad here), which the trapezoidal relation turns into a rate 2 dq / h.
      const double rest_tolerance = 2.0 * RoundOffFloor(std::abs(s.position[0])) / s.dt;  // [rad/s]
      EXPECT_NEAR(s.velocity[0], 0.0, rest_tolerance) << "t = " << s.t;
    }
  }
}

TEST(Friction, EqualCoefficientsGivePlainCoulomb) {
  constexpr double kOmega0 = 10.0, kV0 = 1.0e-4;
  const test::Trace run = test::RunTrace(FrictionalRotor(kOmega0, Friction(kMuK, kMuK, kV0), 15.0));
  const double t_star = kInertia * kOmega0 / kKineticTorque;
  constexpr double kStopTimeTolerance = 1.0e-3;  // as in the spin-down test
  EXPECT_NEAR(FirstStickTime(run), t_star, kStopTimeTolerance * t_star);
  EXPECT_TRUE(run.samples.back().friction[0].sticking);
}

// The rotor at rest under a moment ramp M = c t from t = 0 to 1 s: stuck until c t_b = mu_s rho N, then sliding
// under mu_k, J omega(t) = c (t^2 - t_b^2) / 2 - T_k (t - t_b).
constexpr double kRampEnd = 1.0;  // [s]

ModelSpec RotorUnderMomentRamp(double rate) {
  ModelSpec spec = FrictionalRotor(0.0, Friction(kMuS, kMuK, 1.0e-4), kRampEnd);
  LoadSpec moment;
  moment.body = "link";
  moment.kind = LoadSpec::Kind::kMoment;
  moment.vector = Vec3(0, rate, 0);
  moment.scale.kind = TimeFunctionSpec::Kind::kLinearRamp;
  moment.scale.value = kRampEnd;
  moment.scale.duration = kRampEnd;
  spec.loads.push_back(moment);
  return spec;
}

// The closed form's speed at t (t_b <= t <= kRampEnd) [rad/s].
double SpeedAt(double rate, double t) {
  const double t_b = kStaticTorque / rate;
  return (rate * (t * t - t_b * t_b) / 2 - kKineticTorque * (t - t_b)) / kInertia;
}

// What a breakaway located up to 2% of a step of dt_max early (F3') costs of speed [rad/s].
double EarlyBreakawaySpeed(double dt_max) {
  return (kStaticTorque - kKineticTorque) * 0.02 * dt_max / kInertia;
}

TEST(Friction, BreakawayWhenTorqueExceedsStaticBound) {
  constexpr double kRate = 1.0, kStep = 1.0e-3;
  ModelSpec spec = RotorUnderMomentRamp(kRate);
  spec.solver.dt_max = kStep;
  const test::Trace run = test::RunTrace(spec);
  const double t_b = kStaticTorque / kRate;
  for (const OutputSample& s : run.samples) {
    if (s.t < t_b - kStep) {
      EXPECT_TRUE(s.friction[0].sticking) << "t = " << s.t;
      // The sticking multiplier balances the step's mean (mid-step) moment, to round-off.
      EXPECT_NEAR(s.friction[0].torque, -kRate * (s.t - s.dt / 2), 1e-12) << "t = " << s.t;
    }
    if (s.t > t_b + kStep) {
      EXPECT_FALSE(s.friction[0].sticking) << "t = " << s.t;
    }
  }
  // Breakaway starts within a step of t_b, which costs at most (c t_b - T_k) h / J of speed.
  const double tolerance = (kRate * t_b - kKineticTorque) * kStep / kInertia;
  EXPECT_NEAR(run.samples.back().velocity[0], SpeedAt(kRate, kRampEnd), tolerance);
}

// The same ramp at the rotor's own steps: a stuck joint has no local error, so they grow to dt_max = 0.05 s, and
// t_b = 0.645 s lies inside one. The crossing of the static bound is located (F3'): the line through the mean
// forces of two steps finds it exactly under a ramp, the step that passes it is redone to end at 98% of it, and
// the breakaway starts there, at most 2% of a step early. Before, it started at the end of the step in which
// the mean force passed the bound, 20 ms late here (8.3e-3 rad/s off at the end of the ramp).
TEST(Friction, BreakawayIsLocatedWithinTheStep) {
  constexpr double kRate = 0.93;
  const ModelSpec spec = RotorUnderMomentRamp(kRate);
  const test::Trace run = test::RunTrace(spec);
  EXPECT_NEAR(run.samples.back().velocity[0], SpeedAt(kRate, kRampEnd), EarlyBreakawaySpeed(spec.solver.dt_max))
      << "2.4e-4 measured";
  for (const OutputSample& s : run.samples) EXPECT_LE(test::StaticBoundRatio(spec, BuildModel(spec), s), 1.0 + 1e-9);
}

// Runs of BreakawayIsLocatedWithinTheStep that land just after the breakaway, which then lies in their last steps
// (docs/theory.md (T12), "Last steps"): at their end, or at an at_times instant they go on from. The step that
// passes the static bound is redone as in the middle of a run, at the size (F3') asks for, and the last steps share
// what is left after it. Each run lands on its time with the closed form's speed there, to the 2% of a step that
// the breakaway may start early.
TEST(Friction, ARunLandingJustAfterTheBreakawayLocatesItAndEndsOnItsTime) {
  constexpr double kRate = 0.93;
  const double t_b = kStaticTorque / kRate;
  for (const double after : {1.0e-3, 1.0e-2, 3.0e-2, 6.0e-2, 0.1}) {  // [s] past t_b, within the ramp
    for (const bool at_instant : {false, true}) {
      const double t_land = t_b + after;
      SCOPED_TRACE("landing " + std::to_string(after) + " s after the breakaway" +
                   (at_instant ? " at an instant" : " at t_end"));
      const ModelSpec spec = RotorUnderMomentRamp(kRate);
      const test::Trace run = test::RunLandingOn(spec, t_land, at_instant);
      const OutputSample* landed = test::SampleAt(run, t_land);
      ASSERT_NE(landed, nullptr);
      EXPECT_NEAR(landed->velocity[0], SpeedAt(kRate, t_land), EarlyBreakawaySpeed(spec.solver.dt_max));
    }
  }
}

// The stick-slip oscillator: mass m on a prismatic joint, gravity across it (N = m g from the joint reaction),
// spring k to a point moving at V (a spring on the joint plus the force k V t). Slip starts at k (V t - x) = F_s;
// during slip u = x - V t + F_k / k obeys m u'' = -k u from u0 = -(F_s - F_k) / k, u0' = -V, and ends when
// x' = 0: w t_slip = 2 pi - 2 atan(A / V), A = (F_s - F_k) w / k, slip distance 2 (F_s - F_k) / k + V t_slip,
// then the stick lasts 2 (F_s - F_k) / (k V).
constexpr double kOscMass = 1.0, kSpring = 100.0, kSpeed = 0.1, kG = 9.81, kStaticMu = 0.4, kKineticMu = 0.3;

ModelSpec StickSlipOscillator() {
  ModelSpec spec = test::Slider(kOscMass, 0.0, 2.2);
  spec.output.rate_hz = 0;
  spec.solver.dt_max = 1.0e-3;
  spec.joints[0].effects[0].springs = {{kSpring, 0.0}};
  FrictionSpec friction;
  friction.mu_s = kStaticMu;
  friction.mu_k = kKineticMu;
  friction.v0 = 1.0e-5;
  spec.joints[0].effects[0].frictions = {friction};
  LoadSpec pull;
  pull.body = "mass";
  pull.vector = Vec3(kSpring * kSpeed, 0, 0);
  pull.scale.kind = TimeFunctionSpec::Kind::kLinearRamp;
  pull.scale.value = 10.0;
  pull.scale.duration = 10.0;
  spec.loads.push_back(pull);
  return spec;
}

struct StickSlipErrors {
  double stick = 0, slip = 0, distance = 0;  ///< largest relative errors over the cycles
  double worst() const { return std::max({stick, slip, distance}); }
};

StickSlipErrors MeasureStickSlip(const test::Trace& run) {
  const double f_s = kStaticMu * kOscMass * kG, f_k = kKineticMu * kOscMass * kG, w = std::sqrt(kSpring / kOscMass);
  const double a = (f_s - f_k) * w / kSpring;
  const double t_slip = (2 * M_PI - 2 * std::atan(a / kSpeed)) / w;
  const double slip_distance = 2 * (f_s - f_k) / kSpring + kSpeed * t_slip;
  const double t_stick = 2 * (f_s - f_k) / (kSpring * kSpeed);
  // Sticking intervals from the events: [stick begins, stick ends].
  std::vector<std::pair<double, double>> sticks;
  double begin = 0;
  for (const EffectEvent& e : run.events) {
    if (e.to == FrictionEffect::kSticking) begin = e.t;
    if (e.from == FrictionEffect::kSticking) sticks.emplace_back(begin, e.t);
  }
  auto position_at = [&run](double t) {
    for (size_t k = 1; k < run.samples.size(); ++k) {
      if (run.samples[k].t >= t - 1e-12) return run.samples[k].position[0];
    }
    return run.samples.back().position[0];
  };
  StickSlipErrors e;
  for (size_t k = 1; k + 1 < sticks.size(); ++k) {
    e.stick = std::max(e.stick, std::abs(sticks[k].second - sticks[k].first - t_stick) / t_stick);
    e.slip = std::max(e.slip, std::abs(sticks[k].first - sticks[k - 1].second - t_slip) / t_slip);
    const double distance = position_at(sticks[k].first) - position_at(sticks[k - 1].second);
    e.distance = std::max(e.distance, std::abs(distance - slip_distance) / slip_distance);
  }
  if (sticks.size() < 3) e.stick = e.slip = e.distance = 1.0;
  return e;
}

TEST(Friction, StickSlipOscillatorMatchesPiecewiseSolution) {
  const ModelSpec spec = StickSlipOscillator();
  const test::Trace run = test::RunTrace(spec);
  const double f_s = kStaticMu * kOscMass * kG;
  ASSERT_FALSE(run.events.empty());
  double first_breakaway = -1;
  for (const EffectEvent& e : run.events) {
    if (e.from == FrictionEffect::kSticking && first_breakaway < 0) first_breakaway = e.t;
  }
  EXPECT_NEAR(first_breakaway, f_s / (kSpring * kSpeed), 2e-3) << "first breakaway at k V t = F_s";
  // The bound is 2%; the transitions are located within a step (1e-3 s of 0.2-0.5 s, with the v0 step
  // rule shrinking the steps before sticking): 1%. At the default dt_max see StickSlipErrorFallsWithTheTolerance.
  constexpr double kPiecewiseTolerance = 0.01;
  const StickSlipErrors errors = MeasureStickSlip(run);
  EXPECT_LT(errors.stick, kPiecewiseTolerance);
  EXPECT_LT(errors.slip, kPiecewiseTolerance);
  EXPECT_LT(errors.distance, kPiecewiseTolerance);
  // Every sample within the static bound (F3), sticking and sliding alike.
  const Model model = BuildModel(spec);
  double worst = 0;
  for (const OutputSample& s : run.samples) worst = std::max(worst, test::StaticBoundRatio(spec, model, s));
  EXPECT_LE(worst, 1.0 + 1e-9);
  // Normal force from the reaction: the weight.
  EXPECT_NEAR(run.samples.back().friction[0].normal_force, kOscMass * kG, 1e-9 * kOscMass * kG);
  // Energy books: mechanical energy + friction work - work of the pull = initial energy.
  const OutputSample& last = run.samples.back();
  constexpr double kBookTolerance = 1.0e-8;  // J; Newton tolerance 1e-12 over ~3000 steps of ~0.05 J
  EXPECT_NEAR(last.total() + last.friction[0].work - last.external_work, run.samples.front().total(), kBookTolerance);
}

// The same oscillator read from test/data as a user runs it, at the default dt_max (0.1 s) and adaptive steps. A
// stuck joint has no local error, so its steps grow to dt_max; the breakaway is located (F3'), the step that slides
// first is no longer than the local error test allows after the jump (F3''), and a given v0 gives way to the
// tolerance's threshold where that is lower (F4). Before, the errors were 25-34% at every tolerance: the slide began
// with steps of 0.1 s and the breakaway was booked at the end of the first one.
TEST(Friction, StickSlipErrorFallsWithTheTolerance) {
  const std::string data = std::string(FLEXMBD_SOURCE_DIR) + "/test/data/";
  const ModelSpec spec = LoadModelSpec(data + "urdf/stick_slip.urdf", data + "yaml/stick_slip.yaml");
  const std::vector<double> tolerances = {1.0e-3, 1.0e-5, 1.0e-7};
  std::vector<double> errors;
  for (double error_tol : tolerances) {
    ModelSpec run = spec;
    run.solver.dt_max = SolverSpec{}.dt_max;
    run.solver.error_tol = error_tol;
    errors.push_back(MeasureStickSlip(test::RunTrace(run)).worst());
  }
  // At least 10x per 100x of tolerance (issue 13); measured 2.8e-3, 6.8e-5, 2.1e-6 (42x, 32x).
  for (size_t k = 1; k < errors.size(); ++k) {
    EXPECT_LT(errors[k], errors[k - 1] / 10) << "error_tol " << tolerances[k];
  }
}

TEST(Friction, RegularisedLawApproachesCoulombAsSpeedShrinks) {
  // omega at 0.9 t* against Coulomb's omega0 - T_k t / J, for shrinking v0.
  constexpr double kOmega0 = 10.0;
  const double t_check = 0.9 * kInertia * kOmega0 / kKineticTorque;
  const double coulomb = kOmega0 - kKineticTorque * t_check / kInertia;
  std::vector<double> errors;
  for (double v0 : {1.0e-2, 2.0e-3, 4.0e-4}) {
    FrictionSpec f = Friction(kMuK, kMuK, v0);
    f.law = FrictionSpec::Law::kRegularised;
    ModelSpec spec = FrictionalRotor(kOmega0, f, t_check);
    spec.solver.dt_max = 0.01;
    errors.push_back(std::abs(test::RunTrace(spec).samples.back().velocity[0] - coulomb));
  }
  EXPECT_LT(errors[1], errors[0]);
  EXPECT_LT(errors[2], errors[1]);
  // At v0 = 4e-4 m/s the torque deficit exp(-rho omega / v0) is below e^-50 until omega < 1 rad/s: what is
  // left is the time discretisation of the smooth law, 1e-3 of the final speed.
  constexpr double kLimitTolerance = 1.0e-3;
  EXPECT_LT(errors[2], kLimitTolerance * coulomb);
}

TEST(Friction, NormalForceOfAStuckPendulumIsItsWeightPlusPreload) {
  // A pendulum held by static friction at rest: the pivot carries the weight m g (hand balance of the body),
  // perpendicular to the hinge axis, so N = m g + N0, and the friction torque balances m g a.
  constexpr double kMassKg = 1.0, kArm = 0.5, kG = 9.81, kRaceRadius = 0.05, kHoldPreload = 500.0;
  ModelSpec spec = test::Pendulum(kMassKg, kArm, 0.01);
  spec.solver.integrator = SolverSpec::Integrator::kEnergyPreserving;
  spec.solver.t_end = 0.2;
  spec.solver.tol = 1.0e-12;
  FrictionSpec f;
  f.mu_s = f.mu_k = 0.3;
  f.radius = kRaceRadius;
  f.preload = kHoldPreload;
  f.v0 = 1.0e-4;
  spec.joints[0].effects[0].frictions = {f};
  const test::Trace run = test::RunTrace(spec);
  for (size_t k = 1; k < run.samples.size(); ++k) {
    const FrictionSample& s = run.samples[k].friction[0];
    EXPECT_TRUE(s.sticking);
    // Static balances solved to the Newton tolerance: 1e-9 relative.
    EXPECT_NEAR(s.normal_force, kMassKg * kG + kHoldPreload, 1e-9 * kHoldPreload);
    EXPECT_NEAR(std::abs(s.torque), kMassKg * kG * kArm, 1e-9 * kMassKg * kG * kArm);
  }
}

TEST(Friction, CoreRejectsNonphysicalSettings) {
  auto message = [](const FrictionSpec& f) {
    try {
      BuildModel(FrictionalRotor(0.0, f, 1.0));
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(Friction(0.1, 0.2, 0.0)),
            "rotor (test): joint 'pivot': friction: mu_s: 0.1 is out of range; expected a static coefficient >= mu_k "
            "(0.200000)");
  FrictionSpec negative_radius = Friction(0.3, 0.2, 0.0);
  negative_radius.radius = -1.0;
  EXPECT_EQ(message(negative_radius),
            "rotor (test): joint 'pivot': friction: radius: -1 is out of range; expected a race radius > 0 [m]");
  FrictionSpec regularised = Friction(0.2, 0.2, 0.0);
  regularised.law = FrictionSpec::Law::kRegularised;
  EXPECT_EQ(message(regularised), "rotor (test): joint 'pivot': friction: v0: 0 is out of range; expected a "
                                  "regularisation speed > 0 [m/s] for the regularised law");
}

}  // namespace friction_test
}  // namespace flexmbd
