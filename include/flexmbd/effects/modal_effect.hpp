#pragma once
/// @file
/// Effects with modes (stops: open / in contact / retracted; friction: sliding / sticking). A step is solved
/// with trial modes (those of its start); once it converges each effect checks its trial mode against the
/// converged step and asks for a different one when the step contradicts it (a stop crossed, a contact that
/// pulls, a stuck joint beyond its static bound), and the step is redone (docs/theory.md, "Effects with
/// modes"). Effects also bound the step size: to resolve impacts and stick-slip transitions.

#include <limits>

#include "flexmbd/elements/element.hpp"

namespace flexmbd {

/// A step redone to locate an event (a stop reached, a slip coming to rest) ends at this fraction of the event's
/// time interpolated linearly over the step: just short of it, so the event falls in the next step.
constexpr double kEventLanding = 0.98;

/// Step sizes an effect asks for after a converged step [s]; infinity means no request.
struct StepLimit {
  double retry = std::numeric_limits<double>::infinity();  ///< reject the step, redo it with this size
  double next = std::numeric_limits<double>::infinity();   ///< largest size of the next step
  void Merge(const StepLimit& other);
};

class ModalEffect : public Element {
 public:
  /// Index of this effect's record in State::effects.
  int slot() const { return slot_; }

  /// The mode the converged step described by ctx must be solved with; its trial mode
  /// ((*ctx.effects)[slot()].mode) when the step is consistent with it.
  virtual int ReviseMode(const StepContext& ctx) const = 0;

  /// The mode in which this effect imposes no constraint on the motion of `state`: the one the velocity
  /// projection (VelocityProjection) solves with, so that it removes only what the joints' constraints forbid.
  virtual int ReleasedMode(const State& state) const = 0;

  /// True when the accepted step from `start` to `end` must leave this effect's motion at rest in its end mode
  /// (a plastic contact): the velocity projection then holds this effect in that mode instead of releasing it.
  /// Rates below `negligible_rate` [rad/s or m/s] are at rest already.
  virtual bool ComesToRest(const State& /*start*/, const State& /*end*/, double /*negligible_rate*/) const {
    return false;
  }

  /// Step-size requests from the converged step ctx that led to `end` (rates of `end` known).
  virtual StepLimit Limit(const StepContext& /*ctx*/, const State& /*end*/) const { return {}; }

  /// True when this effect's mode changes leave the velocities continuous (an elastic contact begins and ends
  /// at zero force): the local error estimate then keeps its history across them and watches the event itself.
  /// Otherwise (an impact, a stick-slip transition) the history restarts after the change.
  virtual bool ModeChangesAreSmooth() const { return false; }

  /// True when the redone steps this effect asks for (Limit's retry) locate its events from the end rates of the
  /// step, which carry the scheme's alternating velocity mode (a slip reversal); false when they come from
  /// positions, which do not (a stop's gap).
  virtual bool LocatesEventsFromEndRates() const { return false; }

  /// Updates `effect` (which holds the converged step's mode and the start's memory) for the accepted step
  /// ctx that led to `end`: memory, events, dissipated work, mode changes decided at the end of a step.
  virtual void Commit(const StepContext& ctx, const State& end, EffectState* effect) const = 0;

 protected:
  explicit ModalEffect(int slot) : slot_(slot) {}
  /// The trial mode of this effect in ctx.
  int TrialMode(const StepContext& ctx) const { return (*ctx.effects)[slot_].mode; }

 private:
  int slot_;
};

}  // namespace flexmbd
