#include "flexmbd/math/time_function.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace {
// Derivative order 0, 1 or 2 of f at t.
double Derivative(const TimeFunctionSpec& f, double t, int order) {
  using Kind = TimeFunctionSpec::Kind;
  switch (f.kind) {
    case Kind::kConstant:
      return order == 0 ? f.value : 0.0;
    case Kind::kLinearRamp:
    case Kind::kCosineRamp: {
      const double s = (t - f.start) / f.duration;
      const double span = f.value - f.offset;
      if (s < 0.0 || s >= 1.0) return order == 0 ? (s < 0.0 ? f.offset : f.value) : 0.0;
      if (f.kind == Kind::kLinearRamp) return order == 0 ? f.offset + span * s : order == 1 ? span / f.duration : 0.0;
      const double w = M_PI / f.duration;
      if (order == 0) return f.offset + 0.5 * span * (1.0 - std::cos(M_PI * s));
      if (order == 1) return 0.5 * span * w * std::sin(M_PI * s);
      return 0.5 * span * w * w * std::cos(M_PI * s);
    }
    case Kind::kRateRamp: {
      // The rate follows a cosine ramp from 0 to `value`; f is its integral from `start`, plus `offset`.
      const double s = (t - f.start) / f.duration;
      if (s < 0.0) return order == 0 ? f.offset : 0.0;
      if (s >= 1.0) {
        return order == 0 ? f.offset + f.value * (t - f.start - 0.5 * f.duration) : order == 1 ? f.value : 0.0;
      }
      if (order == 0) return f.offset + f.value * f.duration * (0.5 * s - std::sin(M_PI * s) / (2.0 * M_PI));
      if (order == 1) return 0.5 * f.value * (1.0 - std::cos(M_PI * s));
      return 0.5 * f.value * (M_PI / f.duration) * std::sin(M_PI * s);
    }
    case Kind::kSine: {
      const double w = 2.0 * M_PI * f.frequency;
      const double arg = t < f.start ? f.phase : w * (t - f.start) + f.phase;
      if (order == 0) return f.offset + f.amplitude * std::sin(arg);
      if (t < f.start) return 0.0;
      return order == 1 ? f.amplitude * w * std::cos(arg) : -f.amplitude * w * w * std::sin(arg);
    }
    case Kind::kTable: {
      FLEXMBD_DEMAND(!f.times.empty() && f.times.size() == f.values.size());
      if (t < f.times.front()) return order == 0 ? f.values.front() : 0.0;
      if (t >= f.times.back()) return order == 0 ? f.values.back() : 0.0;
      const auto upper = std::upper_bound(f.times.begin(), f.times.end(), t);
      const size_t j = static_cast<size_t>(upper - f.times.begin());
      const double slope = (f.values[j] - f.values[j - 1]) / (f.times[j] - f.times[j - 1]);
      return order == 0 ? f.values[j - 1] + slope * (t - f.times[j - 1]) : order == 1 ? slope : 0.0;
    }
  }
  return 0.0;
}

// The rate jump at a table's abscissa j (the table is held outside its span), if the slopes either side differ.
std::optional<RateJump> TableKink(const TimeFunctionSpec& f, size_t j) {
  auto slope = [&f](size_t k) { return (f.values[k + 1] - f.values[k]) / (f.times[k + 1] - f.times[k]); };
  const double before = j == 0 ? 0.0 : slope(j - 1);
  const double after = j + 1 == f.times.size() ? 0.0 : slope(j);
  if (before == after) return std::nullopt;
  return RateJump{f.times[j], before, after};
}

// The rate jumps of the kinds with at most two, in time order (tables are searched instead).
std::vector<RateJump> FewRateJumps(const TimeFunctionSpec& f) {
  using Kind = TimeFunctionSpec::Kind;
  std::vector<RateJump> jumps;
  if (f.kind == Kind::kLinearRamp && f.value != f.offset) {
    const double rate = (f.value - f.offset) / f.duration;
    jumps.push_back({f.start, 0.0, rate});
    jumps.push_back({f.start + f.duration, rate, 0.0});
  } else if (f.kind == Kind::kSine) {
    const double rate = Derivative(f, f.start, 1);
    if (rate != 0.0) jumps.push_back({f.start, 0.0, rate});
  }
  return jumps;
}
}  // namespace

double Evaluate(const TimeFunctionSpec& f, double t) { return Derivative(f, t, 0); }
double EvaluateRate(const TimeFunctionSpec& f, double t) { return Derivative(f, t, 1); }
double EvaluateSecondRate(const TimeFunctionSpec& f, double t) { return Derivative(f, t, 2); }

std::optional<RateJump> RateJumpNear(const TimeFunctionSpec& f, double t, double tolerance) {
  if (f.kind == TimeFunctionSpec::Kind::kTable) {
    FLEXMBD_DEMAND(!f.times.empty() && f.times.size() == f.values.size());
    const auto near = std::lower_bound(f.times.begin(), f.times.end(), t - tolerance);
    if (near == f.times.end() || *near > t + tolerance) return std::nullopt;
    return TableKink(f, static_cast<size_t>(near - f.times.begin()));
  }
  for (const RateJump& jump : FewRateJumps(f)) {
    if (std::abs(jump.t - t) <= tolerance) return jump;
  }
  return std::nullopt;
}

std::vector<double> Breakpoints(const TimeFunctionSpec& f) {
  using Kind = TimeFunctionSpec::Kind;
  switch (f.kind) {
    case Kind::kConstant:
    case Kind::kRateRamp:
      return {};
    case Kind::kLinearRamp:
    case Kind::kCosineRamp:
      return {f.start, f.start + f.duration};
    case Kind::kSine:
      return {f.start};
    case Kind::kTable:
      return f.times;
  }
  return {};
}

ValueRange RangeOver(const TimeFunctionSpec& f, double t0, double t1) {
  std::vector<double> instants = {t0, t1};
  for (double t : Breakpoints(f)) {
    if (t > t0 && t < t1) instants.push_back(t);
  }
  if (f.kind == TimeFunctionSpec::Kind::kSine && f.frequency > 0.0) {
    // The first extremes after the sine starts in the interval: a greatest and a least (three for the round-off of the
    // first instant, which may fall just before `from`); later ones repeat their values.
    const double from = std::max(t0, f.start), w = 2.0 * M_PI * f.frequency;
    const double first = std::ceil((w * (from - f.start) + f.phase - 0.5 * M_PI) / M_PI);
    for (double k = first; k < first + 3.0; k += 1.0) {
      const double t = f.start + (0.5 * M_PI + k * M_PI - f.phase) / w;
      if (t >= from && t <= t1) instants.push_back(t);
    }
  }
  std::sort(instants.begin(), instants.end());
  ValueRange range{Evaluate(f, instants.front()), Evaluate(f, instants.front()), instants.front(), instants.front()};
  for (double t : instants) {
    const double value = Evaluate(f, t);
    if (value < range.least) range = {value, range.greatest, t, range.t_greatest};
    if (value > range.greatest) range = {range.least, value, range.t_least, t};
  }
  return range;
}

}  // namespace flexmbd
