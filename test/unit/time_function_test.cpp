// Time functions (include/flexmbd/math/time_function.hpp): values, rates and second rates against hand values
// and central finite differences.

#include <gtest/gtest.h>

#include <cmath>

#include "flexmbd/math/time_function.hpp"

namespace flexmbd {
namespace time_function_test {

// Hand values are computed with the same formulas in double: a few ulp of O(1..10) values.
constexpr double kHandValue = 1.0e-13;
// Central differences with step 1e-5 of O(1) functions with O(10) third derivatives: truncation ~1e-9,
// round-off ~1e-16 / 1e-5 = 1e-11.
constexpr double kStep = 1.0e-5;
constexpr double kFiniteDifference = 1.0e-7;

using Kind = TimeFunctionSpec::Kind;

TimeFunctionSpec Ramp(Kind kind) {
  TimeFunctionSpec f;
  f.kind = kind;
  f.offset = 0.5;
  f.value = 2.5;
  f.start = 1.0;
  f.duration = 2.0;
  return f;
}

TimeFunctionSpec Sine() {
  TimeFunctionSpec f;
  f.kind = Kind::kSine;
  f.offset = 0.2;
  f.amplitude = 1.5;
  f.frequency = 0.75;
  f.phase = 0.4;
  f.start = 0.5;
  return f;
}

TimeFunctionSpec Table() {
  TimeFunctionSpec f;
  f.kind = Kind::kTable;
  f.times = {0.0, 1.0, 3.0, 4.0};
  f.values = {1.0, 3.0, 2.0, 2.0};
  return f;
}

// Checks rate and second rate against central differences of the lower derivative at smooth points.
void ExpectRatesMatchFiniteDifferences(const TimeFunctionSpec& f, double t) {
  const double rate = (Evaluate(f, t + kStep) - Evaluate(f, t - kStep)) / (2.0 * kStep);
  const double second = (EvaluateRate(f, t + kStep) - EvaluateRate(f, t - kStep)) / (2.0 * kStep);
  EXPECT_NEAR(EvaluateRate(f, t), rate, kFiniteDifference) << "t " << t;
  EXPECT_NEAR(EvaluateSecondRate(f, t), second, kFiniteDifference) << "t " << t;
}

TEST(TimeFunction, ConstantHasItsValueAndNoRates) {
  // Reference: f = value, f' = f'' = 0 (exact).
  TimeFunctionSpec f;
  f.value = -3.25;
  for (double t : {-1.0, 0.0, 2.0, 1.0e3}) {
    EXPECT_EQ(Evaluate(f, t), -3.25);
    EXPECT_EQ(EvaluateRate(f, t), 0.0);
    EXPECT_EQ(EvaluateSecondRate(f, t), 0.0);
  }
}

TEST(TimeFunction, DefaultLoadScaleIsOne) {
  // Reference: LoadSpec documents a constant scale of 1 by default (exact).
  EXPECT_EQ(Evaluate(LoadSpec().scale, 7.0), 1.0);
}

TEST(TimeFunction, LinearRampMatchesHandValues) {
  // Reference: f = offset + (value - offset) s, s = (t - start)/duration clipped to [0, 1]; f' = 1 on the ramp.
  const TimeFunctionSpec f = Ramp(Kind::kLinearRamp);
  EXPECT_NEAR(Evaluate(f, 0.0), 0.5, kHandValue);
  EXPECT_NEAR(Evaluate(f, 1.5), 0.5 + 2.0 * 0.25, kHandValue);
  EXPECT_NEAR(Evaluate(f, 2.0), 1.5, kHandValue);
  EXPECT_NEAR(Evaluate(f, 10.0), 2.5, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 0.5), 0.0, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 2.2), 1.0, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 3.5), 0.0, kHandValue);
  EXPECT_EQ(EvaluateSecondRate(f, 2.2), 0.0);
}

TEST(TimeFunction, LinearRampRatesAtKinksAreRightDerivatives) {
  // Reference: the header's convention: at start the right derivative is the ramp slope, at the end it is 0.
  const TimeFunctionSpec f = Ramp(Kind::kLinearRamp);
  EXPECT_NEAR(EvaluateRate(f, 1.0), 1.0, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 3.0), 0.0, kHandValue);
  EXPECT_NEAR(Evaluate(f, 3.0), 2.5, kHandValue);
}

TEST(TimeFunction, LinearRampRatesMatchFiniteDifferences) {
  // Reference: central differences inside the ramp and on the holds.
  const TimeFunctionSpec f = Ramp(Kind::kLinearRamp);
  for (double t : {0.2, 1.3, 2.0, 2.9, 4.0}) ExpectRatesMatchFiniteDifferences(f, t);
}

TEST(TimeFunction, CosineRampMatchesHandValues) {
  // Reference: f = offset + (value - offset)(1 - cos(pi s))/2; f' = (value - offset) (pi/duration) sin(pi s)/2,
  // f'' = (value - offset) (pi/duration)^2 cos(pi s)/2; offset before start, value after the end.
  const TimeFunctionSpec f = Ramp(Kind::kCosineRamp);
  const double w = M_PI / 2.0;
  EXPECT_NEAR(Evaluate(f, -5.0), 0.5, kHandValue);
  EXPECT_NEAR(Evaluate(f, 1.0), 0.5, kHandValue);
  EXPECT_NEAR(Evaluate(f, 2.0), 1.5, kHandValue);
  EXPECT_NEAR(Evaluate(f, 1.5), 0.5 + 2.0 * (1.0 - std::cos(M_PI / 4.0)) / 2.0, kHandValue);
  EXPECT_NEAR(Evaluate(f, 3.0), 2.5, kHandValue);
  EXPECT_NEAR(Evaluate(f, 50.0), 2.5, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 2.0), 2.0 * w / 2.0, kHandValue);
  EXPECT_NEAR(EvaluateSecondRate(f, 1.5), 2.0 * w * w * std::cos(M_PI / 4.0) / 2.0, kHandValue);
  EXPECT_NEAR(EvaluateSecondRate(f, 2.0), 0.0, kHandValue);
  for (double t : {0.0, 3.5}) {
    EXPECT_EQ(EvaluateRate(f, t), 0.0) << "t " << t;
    EXPECT_EQ(EvaluateSecondRate(f, t), 0.0) << "t " << t;
  }
}

TEST(TimeFunction, CosineRampRatesMatchFiniteDifferences) {
  // Reference: central differences inside the ramp and on the holds.
  const TimeFunctionSpec f = Ramp(Kind::kCosineRamp);
  for (double t : {0.3, 1.2, 1.7, 2.0, 2.6, 2.95, 4.5}) ExpectRatesMatchFiniteDifferences(f, t);
}

TEST(TimeFunction, CosineRampIsSmoothAtItsEnds) {
  // Reference: the value and rate are continuous at start and end: f' -> 0 at both ends.
  // Rate one step 1e-9 inside the ramp: ~ span w^2/2 * 1e-9 < 1e-8.
  constexpr double kContinuity = 1.0e-8;
  const TimeFunctionSpec f = Ramp(Kind::kCosineRamp);
  EXPECT_NEAR(EvaluateRate(f, 1.0 + 1.0e-9), 0.0, kContinuity);
  EXPECT_NEAR(EvaluateRate(f, 3.0 - 1.0e-9), 0.0, kContinuity);
  EXPECT_NEAR(Evaluate(f, 3.0 - 1.0e-9), 2.5, kContinuity);
}

TEST(TimeFunction, RateRampMatchesHandValues) {
  // Reference: the rate f' = value (1 - cos(pi s))/2 over the ramp, value after it; f = offset +
  // value duration (s/2 - sin(pi s)/(2 pi)) on the ramp, then offset + value (t - start - duration/2);
  // f'' = value (pi/duration) sin(pi s)/2. Ramp(): offset 0.5, rate 2.5, start 1, duration 2.
  const TimeFunctionSpec f = Ramp(Kind::kRateRamp);
  EXPECT_NEAR(Evaluate(f, -5.0), 0.5, kHandValue);
  EXPECT_NEAR(Evaluate(f, 1.0), 0.5, kHandValue);
  EXPECT_NEAR(Evaluate(f, 2.0), 0.5 + 2.5 * 2.0 * (0.25 - 1.0 / (2.0 * M_PI)), kHandValue);
  EXPECT_NEAR(Evaluate(f, 3.0), 0.5 + 2.5 * 1.0, kHandValue);
  EXPECT_NEAR(Evaluate(f, 13.0), 0.5 + 2.5 * 11.0, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 2.0), 2.5 / 2.0, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 7.0), 2.5, kHandValue);
  EXPECT_NEAR(EvaluateSecondRate(f, 2.0), 2.5 * (M_PI / 2.0) / 2.0, kHandValue);
  for (double t : {0.0, 3.5}) EXPECT_EQ(EvaluateSecondRate(f, t), 0.0) << "t " << t;
  EXPECT_EQ(EvaluateRate(f, 0.0), 0.0);
}

TEST(TimeFunction, RateRampRatesMatchFiniteDifferences) {
  // Reference: central differences inside the ramp and on the holds; f and f' are continuous at both ends.
  const TimeFunctionSpec f = Ramp(Kind::kRateRamp);
  for (double t : {0.3, 1.2, 1.7, 2.0, 2.6, 2.95, 4.5}) ExpectRatesMatchFiniteDifferences(f, t);
}

TEST(TimeFunction, SineMatchesHandValues) {
  // Reference: f = offset + A sin(2 pi nu (t - start) + phase) from start; offset + A sin(phase) before it,
  // with zero rates there.
  const TimeFunctionSpec f = Sine();
  const double w = 2.0 * M_PI * 0.75;
  EXPECT_NEAR(Evaluate(f, 0.0), 0.2 + 1.5 * std::sin(0.4), kHandValue);
  EXPECT_EQ(EvaluateRate(f, 0.0), 0.0);
  EXPECT_EQ(EvaluateSecondRate(f, 0.0), 0.0);
  EXPECT_NEAR(Evaluate(f, 0.5), 0.2 + 1.5 * std::sin(0.4), kHandValue);
  const double t = 1.3, arg = w * (t - 0.5) + 0.4;
  EXPECT_NEAR(Evaluate(f, t), 0.2 + 1.5 * std::sin(arg), kHandValue);
  EXPECT_NEAR(EvaluateRate(f, t), 1.5 * w * std::cos(arg), kHandValue);
  EXPECT_NEAR(EvaluateSecondRate(f, t), -1.5 * w * w * std::sin(arg), kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 0.5), 1.5 * w * std::cos(0.4), kHandValue);
}

TEST(TimeFunction, SineRatesMatchFiniteDifferences) {
  // Reference: central differences after the start and on the hold before it.
  const TimeFunctionSpec f = Sine();
  for (double t : {0.1, 0.6, 1.0, 2.7, 10.3}) ExpectRatesMatchFiniteDifferences(f, t);
}

TEST(TimeFunction, TableInterpolatesLinearly) {
  // Reference: piecewise linear through (0,1), (1,3), (3,2), (4,2); slope of the piece, zero curvature.
  const TimeFunctionSpec f = Table();
  EXPECT_NEAR(Evaluate(f, 0.25), 1.5, kHandValue);
  EXPECT_NEAR(Evaluate(f, 1.0), 3.0, kHandValue);
  EXPECT_NEAR(Evaluate(f, 2.0), 2.5, kHandValue);
  EXPECT_NEAR(Evaluate(f, 3.5), 2.0, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 0.5), 2.0, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 2.0), -0.5, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 3.5), 0.0, kHandValue);
  EXPECT_EQ(EvaluateSecondRate(f, 2.0), 0.0);
}

TEST(TimeFunction, TableHoldsOutsideItsRange) {
  // Reference: held constant at the first value before and the last value after the table, zero rates.
  const TimeFunctionSpec f = Table();
  EXPECT_EQ(Evaluate(f, -2.0), 1.0);
  EXPECT_EQ(Evaluate(f, 9.0), 2.0);
  EXPECT_EQ(EvaluateRate(f, -2.0), 0.0);
  EXPECT_EQ(EvaluateRate(f, 9.0), 0.0);
  EXPECT_EQ(EvaluateSecondRate(f, 9.0), 0.0);
}

TEST(TimeFunction, TableRatesAtKnotsAreRightDerivatives) {
  // Reference: the header's convention "one-sided at the kinks of ramps and tables: the right derivative":
  // at each knot the slope of the piece that starts there (0 after the last knot), as for the ramps, whose
  // rate at `start` is the ramp slope.
  const TimeFunctionSpec f = Table();
  EXPECT_NEAR(EvaluateRate(f, 1.0), -0.5, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 3.0), 0.0, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 4.0), 0.0, kHandValue);
  EXPECT_NEAR(EvaluateRate(f, 0.0), 2.0, kHandValue);
}

// Instants of a rate jump are found to this tolerance [s] in the tests below: far below any step.
constexpr double kSameInstant = 1.0e-12;

void ExpectJump(const std::optional<RateJump>& jump, double t, double before, double after) {
  ASSERT_TRUE(jump.has_value()) << "no jump at t " << t;
  EXPECT_EQ(jump->t, t);
  EXPECT_NEAR(jump->before, before, kHandValue) << "t " << t;
  EXPECT_NEAR(jump->after, after, kHandValue) << "t " << t;
}

TEST(TimeFunction, TableRateJumpsAtItsKinksAndItsHeldEnds) {
  // Reference: slopes 2, -0.5, 0 between the knots 0, 1, 3, 4 and 0 outside: jumps 0 -> 2 at 0, 2 -> -0.5 at 1,
  // -0.5 -> 0 at 3; none at 4, where the last piece is flat like the hold after it.
  const TimeFunctionSpec f = Table();
  ExpectJump(RateJumpNear(f, 0.0, kSameInstant), 0.0, 0.0, 2.0);
  ExpectJump(RateJumpNear(f, 1.0 + 0.1 * kSameInstant, kSameInstant), 1.0, 2.0, -0.5);
  ExpectJump(RateJumpNear(f, 3.0 - 0.1 * kSameInstant, kSameInstant), 3.0, -0.5, 0.0);
  EXPECT_FALSE(RateJumpNear(f, 4.0, kSameInstant).has_value());
  EXPECT_FALSE(RateJumpNear(f, 2.0, kSameInstant).has_value());
}

TEST(TimeFunction, LinearRampAndSineRateJumpWhereTheyStartAndStop) {
  // Reference: the linear ramp turns its rate (2.5 - 0.5) / 2 = 1 on at start = 1 and off at start + duration = 3;
  // the sine starts at 0.5 at its rate amplitude 2 pi frequency cos(phase).
  const TimeFunctionSpec ramp = Ramp(Kind::kLinearRamp);
  ExpectJump(RateJumpNear(ramp, 1.0, kSameInstant), 1.0, 0.0, 1.0);
  ExpectJump(RateJumpNear(ramp, 3.0, kSameInstant), 3.0, 1.0, 0.0);
  EXPECT_FALSE(RateJumpNear(ramp, 2.0, kSameInstant).has_value());
  const TimeFunctionSpec sine = Sine();
  ExpectJump(RateJumpNear(sine, 0.5, kSameInstant), 0.5, 0.0, 1.5 * 2.0 * M_PI * 0.75 * std::cos(0.4));
  EXPECT_FALSE(RateJumpNear(sine, 1.0, kSameInstant).has_value());
}

TEST(TimeFunction, SmoothLawsHaveNoRateJump) {
  // Reference: the cosine ramp's rate rises from 0 and falls back to 0, the rate ramp's rises from 0 to its value
  // and stays (both continuous): a drive on them never starts a step with a jump of its rate, and its runs are
  // stepped as before rate jumps were handled.
  for (Kind kind : {Kind::kCosineRamp, Kind::kRateRamp, Kind::kConstant}) {
    const TimeFunctionSpec f = Ramp(kind);
    for (double t : {1.0, 3.0}) EXPECT_FALSE(RateJumpNear(f, t, kSameInstant).has_value()) << "t " << t;
  }
}

TEST(TimeFunction, BreakpointsAreWhereTheValueOrItsFirstTwoRatesJump) {
  // Reference: the formulas of the header: a linear ramp kinks at its start and end, a cosine ramp's f'' jumps there
  // (by +-(value - offset) (pi/duration)^2 / 2), a sine's rate jumps at its start, a table kinks at every abscissa; a
  // rate ramp's f'' = value (pi/duration) sin(pi s)/2 is continuous, and a constant has none (exact).
  using Times = std::vector<double>;
  EXPECT_EQ(Breakpoints(Ramp(Kind::kLinearRamp)), (Times{1.0, 3.0}));
  EXPECT_EQ(Breakpoints(Ramp(Kind::kCosineRamp)), (Times{1.0, 3.0}));
  EXPECT_EQ(Breakpoints(Sine()), (Times{0.5}));
  EXPECT_EQ(Breakpoints(Table()), (Times{0.0, 1.0, 3.0, 4.0}));
  EXPECT_TRUE(Breakpoints(Ramp(Kind::kRateRamp)).empty());
  EXPECT_TRUE(Breakpoints(TimeFunctionSpec()).empty());
}

void ExpectRange(const ValueRange& range, double least, double t_least, double greatest, double t_greatest) {
  EXPECT_NEAR(range.least, least, kHandValue);
  EXPECT_NEAR(range.t_least, t_least, kHandValue);
  EXPECT_NEAR(range.greatest, greatest, kHandValue);
  EXPECT_NEAR(range.t_greatest, t_greatest, kHandValue);
}

TEST(TimeFunction, RangeOfASineIsItsOffsetPlusOrMinusItsAmplitudeWhereItsArgumentIsPiOverTwoPlusKPi) {
  // Reference: 0.2 + 1.5 sin(1.5 pi (t - 0.5) + 0.4) peaks at 1.7 where the argument is pi/2, dips to -1.3 where it is
  // 3 pi/2, and holds 0.2 + 1.5 sin(0.4) before its start.
  const double w = 1.5 * M_PI;
  ExpectRange(RangeOver(Sine(), 0.0, 10.0), -1.3, 0.5 + (1.5 * M_PI - 0.4) / w, 1.7, 0.5 + (0.5 * M_PI - 0.4) / w);
  // a window that ends before the first peak: the sine rises from its start, the least is the value held before it
  ExpectRange(RangeOver(Sine(), 0.0, 0.6), 0.2 + 1.5 * std::sin(0.4), 0.0, 0.2 + 1.5 * std::sin(0.1 * w + 0.4), 0.6);
}

TEST(TimeFunction, RangeOfRampsAndTablesIsTakenAtTheirBreakpointsOrTheWindowsEnds) {
  // Reference: the hand values of the tests above (0.5 -> 2.5 over [1, 3]; a rate of 2.5 reached over [1, 3]).
  ExpectRange(RangeOver(Ramp(Kind::kLinearRamp), 0.0, 2.0), 0.5, 0.0, 1.5, 2.0);
  ExpectRange(RangeOver(Ramp(Kind::kCosineRamp), 0.0, 10.0), 0.5, 0.0, 2.5, 3.0);
  ExpectRange(RangeOver(Ramp(Kind::kRateRamp), 0.0, 5.0), 0.5, 0.0, 0.5 + 2.5 * (5.0 - 1.0 - 1.0), 5.0);
  ExpectRange(RangeOver(Table(), 0.0, 4.0), 1.0, 0.0, 3.0, 1.0);
  ExpectRange(RangeOver(Table(), 2.0, 2.0), 2.5, 2.0, 2.5, 2.0);
}

}  // namespace time_function_test
}  // namespace flexmbd
