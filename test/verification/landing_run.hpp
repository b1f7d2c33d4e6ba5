#pragma once
// Runs a case so that it lands on a chosen time, at its end or at an instant it goes on from (docs/theory.md
// (T12), "Last steps"), and checks the landing.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "run_trace.hpp"

namespace flexmbd {
namespace test {

// The sample at time t, or nullptr: a run lands a step on t_end and on each instant, to a few ulp of them.
inline const OutputSample* SampleAt(const Trace& run, double t) {
  constexpr double kLanded = 1.0e-12;  // [s]
  for (const OutputSample& s : run.samples) {
    if (std::abs(s.t - t) <= kLanded) return &s;
  }
  return nullptr;
}

// Runs `spec` with t_land as its t_end, or (`at_instant`) as an instant of Simulation::Run that it goes on from for
// 0.05 s; expects it to end on its t_end and to hand over the state at t_land. The sample at t_land is
// SampleAt(run, t_land).
inline Trace RunLandingOn(ModelSpec spec, double t_land, bool at_instant) {
  constexpr double kGoOn = 0.05;  // [s]
  spec.solver.t_end = at_instant ? t_land + kGoOn : t_land;
  Trace run;
  EXPECT_NO_THROW(run = RunTrace(spec, at_instant ? std::vector<double>{t_land} : std::vector<double>{}));
  if (!run.samples.empty()) {
    EXPECT_DOUBLE_EQ(run.samples.back().t, spec.solver.t_end);
  }
  EXPECT_EQ(run.instants.size(), at_instant ? 1u : 0u);
  if (!run.instants.empty()) {
    EXPECT_DOUBLE_EQ(run.instants[0], t_land);
  }
  return run;
}

}  // namespace test
}  // namespace flexmbd
