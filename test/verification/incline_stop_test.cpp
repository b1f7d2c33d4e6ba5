// A block sliding into a rigid stop on an incline (issue 13, docs/theory.md (C5')): decelerating uniformly it has
// no local error, so its steps grow to dt_max, and the step that met the stop held it there for its whole length
// (65 ms) before the rebound left. Read from test/data the way a user runs it, at the default solver settings and
// with the YAML's error_tol changed.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>

#include "flexmbd/effects/friction_effect.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "run_trace.hpp"
#include "yaml_text.hpp"

namespace flexmbd {
namespace incline_stop_test {

// The YAML's gravity along the slide (downhill, +x) and across it [m/s^2]: 9.81 m/s^2 at 30 deg.
constexpr double kAlong = 4.905, kAcross = 8.49571;
constexpr double kMuK = 0.6, kStartSpeed = 1.0, kStop = 2.0;  // [-], [m/s], [m]
// Decelerations sliding downhill and uphill [m/s^2], and the jump between them at the rebound, where the friction
// turns: 2 mu_k g cos 30 (a 1 kg block).
constexpr double kDownhill = kMuK * kAcross - kAlong, kUphill = kMuK * kAcross + kAlong;
constexpr double kJump = kDownhill + kUphill;
// The energy-decaying scheme's rebound (C3) at rho_inf 0.6 (alpha_inf 3/64): (1/2 - alpha) / (1/2 + alpha).
constexpr double kDecayingRebound = 29.0 / 35.0;

struct Outcome {
  double rebound = 0;    ///< the rebound speed over the approach speed of the impact's step
  double t_stick = 0;    ///< when the block sticks after its rebound [s]
  double x_rest = 0;     ///< where it rests [m]
  double books = 0;      ///< energy at the end plus energy dissipated less the initial energy [J]
  double impact_dt = 0;  ///< the impact's step [s]
};

// The case as shipped ("" keeps its solver line), or with `solver` added to its solver settings.
Outcome RunIncline(const std::string& solver) {
  const std::string data = std::string(FLEXMBD_SOURCE_DIR) + "/test/data/";
  std::string yaml = test::ReadFile(data + "yaml/incline_rigid_stops.yaml");
  if (!solver.empty()) yaml = test::Replaced(yaml, "t_end: 3.0", "t_end: 3.0, " + solver);
  const ModelSpec spec = LoadModelSpecFromStrings(test::ReadFile(data + "urdf/stick_slip.urdf"), "stick_slip.urdf",
                                                  YAML::Load(yaml), "incline_rigid_stops.yaml");
  const test::Trace run = test::RunTrace(spec);
  const Model model = BuildModel(spec);
  Outcome out;
  const size_t upper = 1;  // the stops in Model::stops() order: lower, upper
  for (size_t k = 1; k < run.samples.size() && out.impact_dt == 0; ++k) {
    if (!run.samples[k].stops[upper].in_contact) continue;
    out.rebound = -run.samples[k].velocity[0] / run.samples[k - 1].velocity[0];
    out.impact_dt = run.samples[k].dt;
  }
  for (const EffectEvent& e : run.events) {
    const bool friction = dynamic_cast<const FrictionEffect*>(model.modal_effects()[e.effect]) != nullptr;
    if (friction && e.to == FrictionEffect::kSticking) out.t_stick = e.t;
  }
  const OutputSample& first = run.samples.front();
  const OutputSample& last = run.samples.back();
  out.x_rest = last.position[0];
  out.books = last.total() + last.dissipated + last.numerical_dissipation - last.external_work - first.total();
  return out;
}

// Closed form for a rebound keeping `rebound` of the approach speed: x = v0 t - a t^2 / 2 reaches the stop, and the
// rebound decelerates at g (sin 30 + mu_k cos 30) to rest (mu_s cos 30 > sin 30: it sticks).
struct ClosedForm {
  double impact_speed, t_stick, x_rest;  // [m/s], [s], [m]
  explicit ClosedForm(double rebound) {
    const double t_impact = (kStartSpeed - std::sqrt(kStartSpeed * kStartSpeed - 2 * kDownhill * kStop)) / kDownhill;
    impact_speed = kStartSpeed - kDownhill * t_impact;
    const double speed = rebound * impact_speed;
    t_stick = t_impact + speed / kUphill;
    x_rest = kStop - speed * speed / (2 * kUphill);
  }
};

// The rebound the scheme gave: the energy-decaying scheme's alpha is on in the impact's step or off (lossless)
// as the sign of its gate fell on the uniform deceleration before it (docs/theory.md, "Choice of alpha"); each
// within 1e-4 of its value (the step's O(h) term alpha h a_prev, 1e-5 at the impact's steps of 2e-5 s).
double SchemeRebound(double measured) {
  constexpr double kReboundTolerance = 1.0e-4;
  if (std::abs(measured - 1.0) < kReboundTolerance) return 1.0;
  EXPECT_NEAR(measured, kDecayingRebound, kReboundTolerance);
  return kDecayingRebound;
}

// At the default error_tol 1e-4 (joint error floor 1e-7 m; the block's 1 m/s at the start is the peak rate). The
// impact's step is centred on the stop and lasts at most 2 error_tol v_peak / jump (C5'), 1.96e-5 s (before: 65 ms),
// so the rebound leaves off by at most jump h / 2 = error_tol v_peak in rate, which the uphill deceleration turns
// into a stick time off by that over kUphill and a rest position off by v_impact times that; the centring leaves at
// most the error test's allowance (floor + error_tol h v_peak) as a shift; the friction captures the slip up to
// 2 v0 before it stops (v0 = 1% of the largest slip speed), 2 v0 / a early, 2.0e-3 s, and (2 v0)^2 / (2 a) short,
// 2.0e-5 m. Measured 9.4e-4 s early and 4.4e-6 m short (before: 64 ms late and 4.2e-4 m short).
TEST(RigidStop, InclineBlockSticksAfterItsReboundWhereTheClosedFormSays) {
  constexpr double kTol = 1.0e-4, kPeak = kStartSpeed, kFloor = 1.0e-7;
  const Outcome run = RunIncline("");
  const ClosedForm exact(SchemeRebound(run.rebound));
  const double longest = 2 * kTol * kPeak / kJump, v0 = 0.01 * kStartSpeed;
  // The code estimates the jump from the impact's step; 1% for its O(h) terms.
  EXPECT_LE(run.impact_dt, 1.01 * longest);
  const double rate_error = kJump * longest / 2, shift = (kFloor + kTol * longest * kPeak) / exact.impact_speed;
  EXPECT_NEAR(run.t_stick, exact.t_stick, rate_error / kUphill + shift + 2 * v0 / kUphill);
  EXPECT_NEAR(run.x_rest, exact.x_rest,
              exact.impact_speed * rate_error / kUphill + kJump * longest * longest / 8 + shift * exact.impact_speed +
                  2 * v0 * v0 / kUphill);
  // The contact force does no work and friction's is booked: what is left is the round-off of the gap held over
  // the impact step (an ulp of 2 m, 4.4e-16 m) times its contact force (2 m v / h = 5.5e4 N), 2.4e-11 J, and the
  // Newton tolerance's; measured 1.2e-12 J.
  constexpr double kBookTolerance = 1.0e-9;  // [J]
  EXPECT_NEAR(run.books, 0.0, kBookTolerance);
}

// The impact step follows error_tol, and so does the friction's capture speed: the errors fall with the tolerance,
// at least 10x per 100x (issue 13), so 10^1.5 over 1e-3 -> 1e-6. Measured 98x on the stick time (8.0e-4 s ->
// 8.1e-6 s) and 1000x on the rest position (4.3e-5 m -> 4.3e-8 m); before, 1.0x and 3.9x.
TEST(RigidStop, InclineBlockReboundErrorFallsWithTheTolerance) {
  const double kFall = std::pow(10.0, 1.5);
  const Outcome coarse = RunIncline("error_tol: 1.0e-3"), fine = RunIncline("error_tol: 1.0e-6");
  const ClosedForm coarse_exact(SchemeRebound(coarse.rebound)), fine_exact(SchemeRebound(fine.rebound));
  EXPECT_LT(std::abs(fine.t_stick - fine_exact.t_stick), std::abs(coarse.t_stick - coarse_exact.t_stick) / kFall);
  EXPECT_LT(std::abs(fine.x_rest - fine_exact.x_rest), std::abs(coarse.x_rest - coarse_exact.x_rest) / kFall);
}

}  // namespace incline_stop_test
}  // namespace flexmbd
