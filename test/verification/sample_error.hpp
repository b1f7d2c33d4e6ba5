#pragma once
// The error of a run's sampled output against a converged run's, as bench/work_precision measures it.

#include <algorithm>
#include <cmath>
#include <vector>

namespace flexmbd {
namespace test {

/// Largest difference of `run` from `reference` over their samples (equal rates, so equal times), relative to the
/// largest magnitude in `reference`. Several signals per sample may be laid one after another.
inline double RelativeSampleError(const std::vector<double>& run, const std::vector<double>& reference) {
  double error = 0, scale = 0;
  for (size_t k = 0; k < reference.size(); ++k) {
    error = std::max(error, std::abs(run[k] - reference[k]));
    scale = std::max(scale, std::abs(reference[k]));
  }
  return error / scale;
}

}  // namespace test
}  // namespace flexmbd
