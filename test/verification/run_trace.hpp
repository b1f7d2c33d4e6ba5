#pragma once
// Runs a hand-written case to its end and keeps what the verification tests look at: every output sample and
// every mode change of the stops and frictional joints.

#include <vector>

#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace test {

struct Trace {
  std::vector<OutputSample> samples;
  std::vector<EffectEvent> events;
};

inline Trace RunTrace(const ModelSpec& spec) {
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  Trace run;
  simulation.Run([&run](const OutputSample& s) { run.samples.push_back(s); });
  run.events = simulation.effect_events();
  return run;
}

}  // namespace test
}  // namespace flexmbd
