#include "flexmbd/solver/effect_events.hpp"

#include <sstream>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/step_context_builder.hpp"

namespace flexmbd {
namespace {
// At most this many intervals are listed per effect: the first ones and the last one.
constexpr size_t kListedIntervals = 6;

// " [a, b] [c, d] ... [y, z] s", eliding the middle of long lists.
std::string ListIntervals(const std::vector<std::pair<double, double>>& intervals) {
  std::ostringstream out;
  for (size_t k = 0; k < intervals.size(); ++k) {
    if (k + 1 == kListedIntervals && intervals.size() > kListedIntervals) {
      out << " ...";
      k = intervals.size() - 1;
    }
    out << " [" << intervals[k].first << ", " << intervals[k].second << ']';
  }
  if (!intervals.empty()) out << " s";
  return out.str();
}

// Intervals of one effect in `mode`, from its events in time order; one still open ends at t_end. An interval of
// zero length (a joint captured at the end of a step that breaks away from the start of the next: a momentary stop
// where its slip turns) is counted in `instants`, not listed.
std::vector<std::pair<double, double>> Intervals(const std::vector<EffectEvent>& events, int effect, int mode,
                                                 int initial_mode, double t_end, int* instants) {
  std::vector<std::pair<double, double>> intervals;
  *instants = 0;
  bool inside = initial_mode == mode;
  double begin = 0;
  auto close = [&](double end) {
    if (end > begin) intervals.emplace_back(begin, end);
    else ++*instants;
  };
  for (const EffectEvent& e : events) {
    if (e.effect != effect) continue;
    if (!inside && e.to == mode) begin = e.t;
    if (inside && e.to != mode) close(e.t);
    inside = e.to == mode;
  }
  if (inside) close(t_end);
  return intervals;
}

// A static analysis has no time and no events: each stop is closed or open in the equilibrium, and friction is
// left out of it (docs/theory.md, "Friction").
std::vector<std::string> DescribeStaticEffects(const Model& model, const State& state) {
  std::vector<std::string> lines;
  StepContextBuilder builder(model);
  const StepContext& at_equilibrium = builder.AtState(state);
  for (size_t k = 0; k < model.stops().size(); ++k) {
    const JointStop& stop = *model.stop_effects()[k];
    const StopSample sample = stop.Sample(state, at_equilibrium);
    std::ostringstream line;
    line << "stop " << model.stops()[k].joint << ' ' << model.stops()[k].stop << ": ";
    if (sample.in_contact) line << "closed in the static equilibrium, contact force " << sample.force << " N";
    else line << "open in the static equilibrium, gap " << stop.Gap(state.q[stop.variable()]) << " m";
    lines.push_back(line.str());
  }
  for (const FrictionInfo& friction : model.frictions()) {
    lines.push_back("friction " + friction.joint + ": left out of the static analysis");
  }
  return lines;
}
}  // namespace

std::vector<std::string> DescribeEffectIntervals(const Model& model, const std::vector<EffectEvent>& events,
                                                 const State& state) {
  if (model.solver().analysis == SolverSpec::Analysis::kStatic) return DescribeStaticEffects(model, state);
  const double t_end = state.t;
  std::vector<std::string> lines;
  for (size_t k = 0; k < model.stops().size(); ++k) {
    const int slot = model.stop_effects()[k]->slot();
    int instants = 0;
    const auto intervals =
        Intervals(events, slot, JointStop::kContact, model.initial_state().effects[slot].mode, t_end, &instants);
    std::ostringstream line;
    line << "stop " << model.stops()[k].joint << ' ' << model.stops()[k].stop << ": " << intervals.size()
         << " contact interval(s)" << ListIntervals(intervals);
    if (instants > 0) line << " and " << instants << " of zero length";
    lines.push_back(line.str());
  }
  for (size_t k = 0; k < model.frictions().size(); ++k) {
    const FrictionEffect& friction = *model.friction_effects()[k];
    const int slot = friction.slot();
    int instants = 0;
    const auto intervals =
        Intervals(events, slot, FrictionEffect::kSticking, model.initial_state().effects[slot].mode, t_end, &instants);
    std::ostringstream line;
    line << "friction " << model.frictions()[k].joint << ": ";
    // The regularised law never sticks: its v0 is the regularisation speed the user gave, not a threshold.
    const bool regularised = friction.spec().law == FrictionSpec::Law::kRegularised;
    if (regularised) line << "regularised, v0 = " << friction.spec().v0 << " m/s (never sticks)";
    else line << "sticking threshold v0 = " << friction.StickingSpeed(state.effects[slot]) << " m/s";
    line << ", largest slip speed " << state.effects[slot].reference << " m/s, dissipated " << state.effects[slot].work
         << " J";
    if (!regularised) line << ", " << intervals.size() << " sticking interval(s)" << ListIntervals(intervals);
    if (instants > 0) line << " and " << instants << " momentary stop(s) of zero length";
    lines.push_back(line.str());
  }
  return lines;
}

}  // namespace flexmbd
