#include "flexmbd/solver/cycle_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>

#include <unsupported/Eigen/FFT>

namespace flexmbd {

CycleStatistics MeasureCycle(const std::vector<double>& x, double dt) {
  CycleStatistics out;
  const size_t n = x.size();
  if (n == 0) return out;
  out.mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(n);
  const auto [low, high] = std::minmax_element(x.begin(), x.end());
  out.amplitude = 0.5 * (*high - *low);
  std::vector<double> centred(n);
  double square = 0;
  for (size_t k = 0; k < n; ++k) {
    centred[k] = x[k] - out.mean;
    square += centred[k] * centred[k];
  }
  out.rms = std::sqrt(square / static_cast<double>(n));
  if (n > 1) out.mean_rate = (x.back() - x.front()) / (static_cast<double>(n - 1) * dt);
  out.one_way = *high > *low && (std::is_sorted(x.begin(), x.end()) || std::is_sorted(x.rbegin(), x.rend()));
  if (n < 4) return out;
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, centred);
  std::vector<double> magnitude(n / 2 + 1);
  for (size_t k = 0; k < magnitude.size(); ++k) magnitude[k] = std::abs(spectrum[k]);
  const size_t peak = std::max_element(magnitude.begin() + 1, magnitude.end()) - magnitude.begin();
  // The component between bins: a sine a fraction d of a bin above bin k leaks into k and k + 1 in the ratio
  // |X[k+1]| / |X[k]| = d / (1 - d) (the record is a rectangular window), so d = r / (1 + r) from the larger
  // neighbour's ratio r; exact for one complex tone, within the leakage of the negative frequency for a real one.
  double shift = 0;
  if (peak + 1 < magnitude.size()) {
    const bool right = magnitude[peak + 1] >= magnitude[peak - 1];
    const double ratio = magnitude[right ? peak + 1 : peak - 1] / magnitude[peak];
    shift = (right ? 1.0 : -1.0) * ratio / (1.0 + ratio);
  }
  out.frequency_hz = (static_cast<double>(peak) + shift) / (static_cast<double>(n) * dt);
  return out;
}

}  // namespace flexmbd
