// Bisection of a fan plot's changes of stability (docs/theory.md, (E9)).

#include "flexmbd/solver/damping_crossing.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace {

// `point` with its modes in the order of `from`'s (the lower end of the bracket), matched by shape.
SweepPoint TrackedFrom(const SweepPoint& from, SweepPoint point) {
  std::vector<SweepPoint> pair{from, std::move(point)};
  TrackModes(&pair);
  return std::move(pair[1]);
}

DampingCrossing Bisect(SweepPoint lower, SweepPoint upper, int k, const std::function<EigenResult(double)>& analyse,
                       double relative_tolerance) {
  const bool unstable_below = Unstable(lower.result.modes[k]);
  Mode upper_mode = upper.result.modes[k];
  while (upper.parameter - lower.parameter > relative_tolerance * std::abs(upper.parameter)) {
    const double p = 0.5 * (lower.parameter + upper.parameter);
    SweepPoint middle = TrackedFrom(lower, SweepPoint{p, analyse(p)});
    if (k >= static_cast<int>(middle.result.modes.size())) {
      throw SolverError("the mode " + std::to_string(k + 1) + " changing stability between " +
                        std::to_string(lower.parameter) + " and " + std::to_string(upper.parameter) +
                        " is not among the modes found at " + std::to_string(p));
    }
    if (Unstable(middle.result.modes[k]) == unstable_below) {
      lower = std::move(middle);
    } else {
      upper.parameter = p;
      upper_mode = middle.result.modes[k];
    }
  }
  DampingCrossing crossing;
  crossing.mode = k;
  crossing.parameter = 0.5 * (lower.parameter + upper.parameter);
  const Mode& unstable = unstable_below ? lower.result.modes[k] : upper_mode;
  crossing.frequency_hz = unstable.frequency_hz;
  crossing.oscillating = unstable.damped_frequency_hz > 0;
  crossing.destabilising = !unstable_below;
  return crossing;
}

}  // namespace

std::vector<DampingCrossing> LocateDampingCrossings(const std::vector<SweepPoint>& points,
                                                    const std::function<EigenResult(double)>& analyse,
                                                    double relative_tolerance) {
  std::vector<DampingCrossing> crossings;
  for (size_t p = 0; p + 1 < points.size(); ++p) {
    const std::vector<Mode>& below = points[p].result.modes;
    const std::vector<Mode>& above = points[p + 1].result.modes;
    for (size_t k = 0; k < below.size() && k < above.size(); ++k) {
      if (Unstable(below[k]) == Unstable(above[k])) continue;
      crossings.push_back(Bisect(points[p], points[p + 1], static_cast<int>(k), analyse, relative_tolerance));
    }
  }
  return crossings;
}

}  // namespace flexmbd
