#pragma once
// The growth rate of a sampled oscillation from its peaks.

#include <cmath>
#include <cstdlib>
#include <vector>

namespace flexmbd {
namespace test {

/// Decay (or growth) rate of an oscillation x(t) over [t0, t1] from its successive peaks: the slope of log|peak|
/// against time by least squares [1/s].
inline double PeakRate(const std::vector<double>& t, const std::vector<double>& x, double t0, double t1) {
  std::vector<double> pt, px;
  for (size_t k = 1; k + 1 < x.size(); ++k) {
    if (t[k] < t0 || t[k] > t1) continue;
    if (std::abs(x[k]) > std::abs(x[k - 1]) && std::abs(x[k]) >= std::abs(x[k + 1])) {
      pt.push_back(t[k]);
      px.push_back(std::log(std::abs(x[k])));
    }
  }
  const double n = pt.size();
  double st = 0, sx = 0, stt = 0, stx = 0;
  for (size_t k = 0; k < pt.size(); ++k) {
    st += pt[k];
    sx += px[k];
    stt += pt[k] * pt[k];
    stx += pt[k] * px[k];
  }
  return (n * stx - st * sx) / (n * stt - st * st);
}

}  // namespace test
}  // namespace flexmbd
