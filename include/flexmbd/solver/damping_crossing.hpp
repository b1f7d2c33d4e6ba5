#pragma once
/// @file
/// Where a mode of a fan plot changes stability (docs/theory.md, "Flutter speed" (E9)): between two neighbouring
/// points of a sweep with different numbers of growing modes, the parameter of the change is bisected on the
/// eigen-analysis itself (not interpolated from the table), on that number rather than on a mode followed by its
/// shape.

#include <functional>
#include <vector>

#include "flexmbd/solver/eigen_analysis.hpp"

namespace flexmbd {

/// One mode's damping ratio crossing zero.
struct DampingCrossing {
  int mode = -1;              ///< column of the fan plot (0-based) of the growing mode of least Re s at the
                              ///< unstable end
  double parameter = 0.0;     ///< the middle of the final bracket
  double frequency_hz = 0.0;  ///< the mode's natural frequency at the unstable end of the final bracket [Hz]
  bool oscillating = true;    ///< complex root (flutter) rather than a real one (divergence)
  bool destabilising = true;  ///< stable below the crossing and unstable above it
};

/// Every change of the number of growing modes between neighbouring points of `points` (tracked, in increasing
/// parameter order), in order of parameter. Each is bisected with analyse(p), the modes at p, until
/// the bracket is narrower than relative_tolerance times its upper end.
std::vector<DampingCrossing> LocateDampingCrossings(const std::vector<SweepPoint>& points,
                                                    const std::function<EigenResult(double)>& analyse,
                                                    double relative_tolerance);

}  // namespace flexmbd
