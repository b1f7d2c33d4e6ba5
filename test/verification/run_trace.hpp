#pragma once
// Runs a hand-written case to its end and keeps what the verification tests look at: every output sample, every
// mode change of the stops and frictional joints, and the times of the states handed over at `instants`.

#include <vector>

#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace test {

struct Trace {
  std::vector<OutputSample> samples;
  std::vector<EffectEvent> events;
  std::vector<double> instants;  ///< the time of the state at each instant the run stopped at [s]
};

inline Trace RunTrace(const ModelSpec& spec, const std::vector<double>& instants = {}) {
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  Trace run;
  simulation.Run([&run](const OutputSample& s) { run.samples.push_back(s); }, instants,
                 [&run](const State& s) { run.instants.push_back(s.t); });
  run.events = simulation.effect_events();
  return run;
}

}  // namespace test
}  // namespace flexmbd
