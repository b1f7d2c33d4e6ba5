#pragma once
/// @file
/// The steps that land on a time the run must reach: its end, and in one step an instant it stops at or a time
/// function's breakpoint (docs/theory.md, (T12), "Last steps").

namespace flexmbd {

/// A step may be stretched by this fraction of itself to land, so that no sliver step is left.
inline constexpr double kLandingStretch = 0.01;
/// The window of the run's last steps before t_end, in proposals: at most this many steps share the time left.
inline constexpr int kLastSteps = 3;

/// The size of the next attempt [s], given the controller's `proposal` [s] and the time `left` [s] to the time the
/// run must land on. Within `window` proposals (each stretched by kLandingStretch at most) the time left in the
/// fewest equal steps that fit; farther away the proposal. After a rejection (`after_rejection`) the proposal, cut
/// to the time left and never stretched, so that every retry is shorter than the step rejected.
double StepToLanding(double proposal, double left, int window, bool after_rejection);

}  // namespace flexmbd
