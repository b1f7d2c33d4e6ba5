// MeasureCycle (the runner's `output.cycle_from` report) on signals whose statistics are known in closed form.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "flexmbd/solver/cycle_statistics.hpp"

namespace flexmbd {
namespace cycle_statistics_test {

std::vector<double> Sampled(double mean, double amplitude, double frequency, double dt, int n) {
  std::vector<double> x(n);
  for (int k = 0; k < n; ++k) x[k] = mean + amplitude * std::sin(2 * M_PI * frequency * k * dt + 0.3);
  return x;
}

TEST(CycleStatistics, SineGivesItsMeanAmplitudeRmsAndFrequency) {
  // 30 s at 200 Hz of 4.21 Hz: 126.3 periods, so the component falls between two 1/30 Hz bins. The ratio of the
  // largest bin and its larger neighbour places it exactly but for the leakage of the negative frequency, of the
  // order of 1 / (2 pi periods) of a bin: a hundredth of a bin bounds it.
  const double dt = 1.0 / 200, frequency = 4.21;
  const int n = 6000;
  const CycleStatistics c = MeasureCycle(Sampled(0.25, 1.5, frequency, dt, n), dt);
  // Mean and RMS over a non-integer number of periods: off by the unfinished period's share, at most
  // amplitude / (pi * periods) for the mean.
  EXPECT_NEAR(c.mean, 0.25, 1.5 / (M_PI * 126.3));
  EXPECT_NEAR(c.rms, 1.5 / std::sqrt(2.0), 1.5 / (M_PI * 126.3));
  // The largest sample is within (2 pi f dt)^2 / 2 of the crest (the nearest sample at most dt / 2 away).
  EXPECT_NEAR(c.amplitude, 1.5, 1.5 * std::pow(2 * M_PI * frequency * dt, 2) / 2);
  EXPECT_NEAR(c.frequency_hz, frequency, 0.01 / (n * dt));
}

TEST(CycleStatistics, LargestComponentWinsOverASmallerOne) {
  const double dt = 0.01;
  std::vector<double> x = Sampled(0.0, 1.0, 2.0, dt, 4000);
  const std::vector<double> small = Sampled(0.0, 0.4, 7.0, dt, 4000);
  for (size_t k = 0; k < x.size(); ++k) x[k] += small[k];
  // 40 s: both components fall on bins (80 and 280 periods), so the frequency is exact to round-off.
  EXPECT_NEAR(MeasureCycle(x, dt).frequency_hz, 2.0, 1e-9);
}

TEST(CycleStatistics, TooFewSamplesGiveNoFrequency) {
  const CycleStatistics c = MeasureCycle({1.0, 3.0, 2.0}, 0.1);
  EXPECT_DOUBLE_EQ(c.mean, 2.0);
  EXPECT_DOUBLE_EQ(c.amplitude, 1.0);
  EXPECT_EQ(c.frequency_hz, 0.0);
  EXPECT_EQ(MeasureCycle({}, 0.1).rms, 0.0);
}

TEST(CycleStatistics, SpinningAngleRunsOneWayAtItsMeanRate) {
  // A rotor's angle: 10 rad/s with a 1P ripple of 0.05 rad (its rate 10 + 0.5 cos never turns negative), 4 s at
  // 100 Hz. It has a mean and a spectrum, but no cycle; its mean rate is (x_last - x_first) / 3.99 s, which the
  // ripple moves by at most 0.1 rad / 3.99 s.
  const double dt = 0.01;
  std::vector<double> x = Sampled(0.0, 0.05, 10.0 / (2 * M_PI), dt, 400);
  for (size_t k = 0; k < x.size(); ++k) x[k] += 10.0 * dt * k;
  const CycleStatistics c = MeasureCycle(x, dt);
  EXPECT_TRUE(c.one_way);
  EXPECT_NEAR(c.mean_rate, 10.0, 0.1 / 3.99);
}

TEST(CycleStatistics, OscillationAndRestDoNotRunOneWay) {
  EXPECT_FALSE(MeasureCycle(Sampled(0.25, 1.5, 4.21, 0.005, 6000), 0.005).one_way);
  // A drift with an oscillation that turns it back now and then is a cycle about a moving mean.
  std::vector<double> x = Sampled(0.0, 1.0, 2.0, 0.01, 400);
  for (size_t k = 0; k < x.size(); ++k) x[k] += 0.05 * k;
  EXPECT_FALSE(MeasureCycle(x, 0.01).one_way);
  EXPECT_FALSE(MeasureCycle(std::vector<double>(10, 3.0), 0.01).one_way);
}

}  // namespace cycle_statistics_test
}  // namespace flexmbd
