// Bisection of a fan plot's changes of stability (docs/theory.md, (E9)).

#include "flexmbd/solver/damping_crossing.hpp"

#include <cmath>
#include <utility>

namespace flexmbd {
namespace {

// A mode grows, for the flutter search, when its damping ratio is below minus kRoundOffMargin and, in a model with
// element states, its frequency is below kResolved of the frequency scale (theory (E9)). Undamped roots of the dense
// first-order solve with element states (E7) come out with damping ratios of round-off size and either sign that drift
// with the speed, the more the nearer the top of the spectrum: in the Goland wing's sweep -1.1e-9 at 1.9e4 Hz (0.16 of
// the scale) and below -1e-6 at 1.21e5 Hz (the scale), the beam's axial and shear roots. Flutter roots sit lower: 11 Hz
// there (1e-4 of the scale), the Conner section's 6 Hz at 0.05 of its scale (its fastest inflow root). A flutter root's
// ratio changes by ~5e-3 per m/s, so the margin moves the located speed by ~2e-4 m/s, 1.5e-6 of it: far inside the 1e-4
// bracket.
constexpr double kRoundOffMargin = 1.0e-6, kResolved = 0.1;

bool Grows(const Mode& mode, const EigenResult& result) {
  return !mode.rigid_body && mode.damping_ratio < -kRoundOffMargin &&
         (result.num_states == 0 || mode.frequency_hz < kResolved * result.frequency_scale_hz);
}

int CountGrowing(const EigenResult& result) {
  int count = 0;
  for (const Mode& mode : result.modes) count += Grows(mode, result) ? 1 : 0;
  return count;
}

// The growing mode nearest the axis, by its growth rate Re s: the one that has just crossed it. Not by the damping
// ratio: a real root that has just crossed (divergence) has ratio -1 however slowly it grows, so a flutter root
// growing since a lower speed, at ratio -0.2, would be taken for it (explore23 aero/flutter_n8.yaml).
int LeastGrowing(const EigenResult& result) {
  int k = -1;
  for (size_t i = 0; i < result.modes.size(); ++i) {
    if (Grows(result.modes[i], result) &&
        (k < 0 || result.modes[i].eigenvalue.real() < result.modes[k].eigenvalue.real())) {
      k = static_cast<int>(i);
    }
  }
  return k;
}

// Bisects [lower, upper] on the number of growing modes, which differs at the two ends: no mode is followed
// across the bracket, so modes that coalesce (whose shapes become alike near flutter) cannot be confused.
DampingCrossing Bisect(SweepPoint lower, SweepPoint upper, const std::function<EigenResult(double)>& analyse,
                       double relative_tolerance) {
  const int below = CountGrowing(lower.result);
  const SweepPoint sweep_lower = lower, sweep_upper = upper;
  while (upper.parameter - lower.parameter > relative_tolerance * std::abs(upper.parameter)) {
    const double p = 0.5 * (lower.parameter + upper.parameter);
    SweepPoint middle{p, analyse(p)};
    (CountGrowing(middle.result) == below ? lower : upper) = std::move(middle);
  }
  const bool destabilising = CountGrowing(upper.result) > below;
  // The unstable end's modes in the order of the sweep's point on that side: the fan plot's columns.
  std::vector<SweepPoint> pair{destabilising ? sweep_upper : sweep_lower, destabilising ? upper : lower};
  TrackModes(&pair);
  const EigenResult& unstable = pair[1].result;
  DampingCrossing crossing;
  crossing.mode = LeastGrowing(unstable);
  crossing.parameter = 0.5 * (lower.parameter + upper.parameter);
  const Mode& mode = unstable.modes[crossing.mode];
  crossing.frequency_hz = mode.frequency_hz;
  crossing.oscillating = mode.damped_frequency_hz > 0;
  crossing.destabilising = destabilising;
  return crossing;
}

}  // namespace

std::vector<DampingCrossing> LocateDampingCrossings(const std::vector<SweepPoint>& points,
                                                    const std::function<EigenResult(double)>& analyse,
                                                    double relative_tolerance) {
  std::vector<DampingCrossing> crossings;
  for (size_t p = 0; p + 1 < points.size(); ++p) {
    if (CountGrowing(points[p].result) == CountGrowing(points[p + 1].result)) continue;
    crossings.push_back(Bisect(points[p], points[p + 1], analyse, relative_tolerance));
  }
  return crossings;
}

}  // namespace flexmbd
