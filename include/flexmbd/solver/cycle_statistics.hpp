#pragma once
/// @file
/// What the runner reports of a settled oscillation (`output.cycle_from`, docs/config.md): a limit cycle's
/// amplitude and frequency from one signal sampled at equal intervals.

#include <vector>

namespace flexmbd {

struct CycleStatistics {
  double mean = 0;          ///< of the samples
  double amplitude = 0;     ///< half the peak-to-peak range
  double rms = 0;           ///< root mean square about the mean
  double frequency_hz = 0;  ///< of the largest Fourier component other than the mean; 0 with fewer than 4 samples
  /// The samples never turn back (each is >= the one before, or each <=) and do change: the signal runs one way
  /// (a spinning rotor's angle) and has no cycle, whatever its spectrum says.
  bool one_way = false;
  double mean_rate = 0;  ///< (last - first) / the time between them [unit/s]
};

/// The statistics of samples x taken every dt seconds.
CycleStatistics MeasureCycle(const std::vector<double>& x, double dt);

}  // namespace flexmbd
