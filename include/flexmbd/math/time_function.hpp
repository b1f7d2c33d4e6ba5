#pragma once
/// @file
/// Scalar time functions for drives and loads (docs/config.md, "time functions").

#include <optional>
#include <vector>

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

/// Value of f(t). Ramps hold `offset` before `start` and `value` after `start + duration`:
/// linear ramp f = offset + (value - offset) s, smooth ramp f = offset + (value - offset)(1 - cos(pi s))/2,
/// s = (t - start)/duration clipped to [0, 1]; sine f = offset + amplitude sin(2 pi frequency (t - start) + phase)
/// for t >= start (offset + amplitude sin(phase) before); table: piecewise linear, held constant outside.
double Evaluate(const TimeFunctionSpec& f, double t);

/// First derivative df/dt (one-sided at the kinks of ramps and tables: the right derivative).
double EvaluateRate(const TimeFunctionSpec& f, double t);

/// Second derivative d2f/dt2 (zero on linear pieces).
double EvaluateSecondRate(const TimeFunctionSpec& f, double t);

/// An instant at which the rate df/dt jumps, with the rates just before and just after it.
struct RateJump {
  double t = 0.0;       ///< [s]
  double before = 0.0;  ///< df/dt just before t
  double after = 0.0;   ///< df/dt just after t
};

/// The jump of df/dt within `tolerance` [s] of t, if f has one there: the kinks of linear ramps and tables (a table's
/// ends too, where it is held), a sine's start at a nonzero rate. Cosine and rate ramps have none.
std::optional<RateJump> RateJumpNear(const TimeFunctionSpec& f, double t, double tolerance);


/// The instants where f, f' or f'' jumps [s], increasing: a ramp's start and end (a rate ramp's f'' is continuous:
/// none), a sine's start, a table's abscissae. The steps of a run land on them (docs/theory.md, "Breakpoints").
std::vector<double> Breakpoints(const TimeFunctionSpec& f);

/// The least and greatest values of f over an interval, and the first instants they are taken at.
struct ValueRange {
  double least = 0.0, greatest = 0.0;      ///< f's unit
  double t_least = 0.0, t_greatest = 0.0;  ///< [s]
};

/// The range of f over [t0, t1] (t0 <= t1): f is monotone between its breakpoints, so its extremes lie at those, at the
/// interval's ends, or, for a sine, where its argument is pi/2 + k pi.
ValueRange RangeOver(const TimeFunctionSpec& f, double t0, double t1);

}  // namespace flexmbd
