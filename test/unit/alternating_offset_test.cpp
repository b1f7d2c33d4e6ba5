// The alternating error of an algebraic variable (AlternatingOffset, docs/theory.md "Algebraic rotations"): from the
// mean rates of three steps of unequal size, a motion of constant second derivative whose step ends carry +-x in turn
// gives x back to round-off, and a smooth motion alone gives an offset of the order of its local error (T12).

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "flexmbd/solver/time_integrator.hpp"

namespace flexmbd {
namespace alternating_offset_test {

// Mean rates of the three steps (sizes h, newest first) that end at t = 0, of the motion `position` with the
// alternating error `x` added at the step ends, +x at t = 0.
template <typename Position>
std::array<double, 3> MeanRates(const Position& position, double x, const std::array<double, 3>& h) {
  std::array<double, 4> ends;  // t = 0, -h0, -h0-h1, -h0-h1-h2
  double t = 0;
  for (int k = 0; k < 4; ++k) {
    ends[k] = position(t) + (k % 2 == 0 ? x : -x);
    if (k < 3) t -= h[k];
  }
  return {(ends[0] - ends[1]) / h[0], (ends[1] - ends[2]) / h[1], (ends[2] - ends[3]) / h[2]};
}

TEST(AlternatingOffset, RecoversTheErrorOnAMotionOfConstantSecondDerivative) {
  const std::array<double, 3> h = {1.0e-6, 2.3e-4, 3.1e-4};  // a short step after long ones, as a landing takes
  const auto parabola = [](double t) { return 0.05 + 2.8 * t - 29.4 * t * t / 2; };
  for (double x : {3.0e-7, -5.0e-7, 0.0}) {
    const std::array<double, 3> u = MeanRates(parabola, x, h);
    // Round-off of mean rates of size 2x/h0 ~ 1: 1e-16 of them times h0, against x of 1e-7.
    EXPECT_NEAR(AlternatingOffset(u[0], u[1], u[2], h), x, 1.0e-15);
  }
}

TEST(AlternatingOffset, OnASmoothMotionIsOfTheOrderOfItsLocalError) {
  // x''' = -omega^3 cos(omega t) A: equal steps give h^3 x''' / 8 (T12's estimate h^3 x''' / 12 times 3/2), to O(h^5).
  const double amplitude = 1.0e-3, omega = 50.0, step = 1.0e-3;
  const auto wave = [&](double t) { return amplitude * std::sin(omega * t); };
  const std::array<double, 3> h = {step, step, step};
  const std::array<double, 3> u = MeanRates(wave, 0.0, h);
  const double third = -amplitude * omega * omega * omega * std::cos(omega * -1.5 * step);
  EXPECT_NEAR(AlternatingOffset(u[0], u[1], u[2], h), step * step * step * third / 8,
              0.05 * std::abs(step * step * step * third / 8));
}

}  // namespace alternating_offset_test
}  // namespace flexmbd
