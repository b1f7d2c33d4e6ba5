#pragma once
/// @file
/// A bound on what a dynamic run writes to its CSV and bag (docs/config.md, "output"): a careless rate_hz or
/// t_end must not fill a disk silently.

#include "flexmbd/model/model.hpp"

namespace flexmbd {

/// Most values (samples x values per sample) a run may write without output.allow_large_output. At up to
/// 24 characters per CSV value (17 significant digits, sign, exponent, comma) that is about 1 GB of CSV;
/// the largest reference case (the antenna, 200 s at 20 Hz) writes about 100 times less.
constexpr double kMaxOutputValues = 4.0e7;

/// Most samples a dynamic run at output.rate_hz > 0 makes when it writes no file: each is still interpolated
/// and passed to the sinks (the node publishes it), so a careless rate (1e18 Hz) is a run that never ends.
/// At a few microseconds a sample that is a few minutes of sampling.
constexpr double kMaxSamplesWithoutFiles = 4.0e7;

/// Values in one output sample: the CSV columns (time, joint variables, reactions, stops, friction, beam
/// stations, energies, step).
long OutputValuesPerSample(const Model& model);

/// Samples a dynamic run writes: t_end x rate_hz + 1, or with rate_hz 0 (every accepted step) the step count
/// at fixed steps of dt, or at least t_end / dt_max with adaptive steps.
double ExpectedOutputSamples(const SolverSpec& solver, const OutputSpec& output);

/// Throws ConfigError naming the model's source, solver.t_end, output.rate_hz (and output.beam_stations when
/// given) if a dynamic run that writes a CSV or a bag would write more than kMaxOutputValues values, or one
/// that writes none would make more than kMaxSamplesWithoutFiles samples at a rate_hz > 0, and
/// output.allow_large_output is not set.
void CheckOutputSize(const Model& model);

}  // namespace flexmbd
