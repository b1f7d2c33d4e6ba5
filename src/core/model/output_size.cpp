#include "flexmbd/model/output_size.hpp"

#include <sstream>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace {
constexpr int kValuesPerVariable = 3;        // position, velocity, effort
constexpr int kValuesPerJoint = 6;           // reaction force and moment
constexpr int kValuesPerStop = 4;            // in_contact, force, torque, approach
constexpr int kValuesPerFriction = 5;        // sticking, torque, normal_force, slip_velocity, work
constexpr int kValuesPerBeamStation = 18;    // loads, strains, displacement, rotation
constexpr int kValuesPerAeroSection = 3;     // lift, moment, hinge moment; then its inflow states
constexpr int kValuesPerRotor = 2;           // inflow, thrust
constexpr int kValuesPerHarmonics = 4;       // a rotor's harmonic inflows and moments
constexpr int kValuesPerSampleHeader = 1;    // t
constexpr int kValuesPerSampleTrailer = 8;   // six energies, dt, iterations
}  // namespace

long OutputValuesPerSample(const Model& model) {
  long aero = 0;
  for (const TypicalSectionAero* section : model.aero_sections()) aero += kValuesPerAeroSection + section->num_states();
  for (const StripStationInfo& station : model.strip_stations()) {
    aero += kValuesPerAeroSection + station.inner->num_states();
  }
  for (const RotorInflow* rotor : model.aero_rotors()) {
    aero += kValuesPerRotor + (rotor->harmonic() ? kValuesPerHarmonics : 0);
  }
  return aero + kValuesPerSampleHeader + kValuesPerVariable * static_cast<long>(model.variable_names().size()) +
         kValuesPerJoint * static_cast<long>(model.joints().size()) +
         kValuesPerStop * static_cast<long>(model.stops().size()) +
         kValuesPerFriction * static_cast<long>(model.frictions().size()) +
         kValuesPerBeamStation * static_cast<long>(model.beam_stations().size()) + kValuesPerSampleTrailer;
}

double ExpectedOutputSamples(const SolverSpec& solver, const OutputSpec& output) {
  if (output.rate_hz > 0) return solver.t_end * output.rate_hz + 1.0;
  return solver.t_end / (solver.adaptive ? solver.dt_max : solver.dt) + 1.0;
}

namespace {

// "<source>: output.rate_hz R Hz and solver.t_end T s give N samples": how every bound's message begins.
std::string SamplesText(const Model& model, double samples) {
  std::ostringstream msg;
  msg << (model.source().empty() ? "" : model.source() + ": ") << "output.rate_hz " << model.output().rate_hz
      << " Hz and solver.t_end " << model.solver().t_end << " s give " << samples << " samples";
  return msg.str();
}

}  // namespace

void CheckOutputSize(const Model& model) {
  const OutputSpec& output = model.output();
  if (model.solver().analysis != SolverSpec::Analysis::kDynamic || output.allow_large_output) return;
  const double samples = ExpectedOutputSamples(model.solver(), output);
  const bool writes = !output.csv.empty() || !output.bag.empty();
  if (!writes) {
    // with rate_hz 0 the samples are the steps, which the run takes anyway
    if (output.rate_hz > 0 && samples > kMaxSamplesWithoutFiles) {
      std::ostringstream msg;
      msg << SamplesText(model, samples) << ", more than " << kMaxSamplesWithoutFiles
          << " (each is interpolated and passed on, with or without an output file); expected a lower rate_hz, a "
             "shorter t_end, or output.allow_large_output: true";
      throw ConfigError(msg.str());
    }
    return;
  }
  const long per_sample = OutputValuesPerSample(model);
  if (!(samples * per_sample > kMaxOutputValues)) return;
  std::ostringstream msg;
  msg << SamplesText(model, samples);
  if (output.rate_hz == 0) {
    msg << " (one per step, at least t_end / dt" << (model.solver().adaptive ? "_max" : "") << ")";
  }
  msg << " of " << per_sample << " values";
  if (!model.beam_stations().empty()) {
    msg << " (" << kValuesPerBeamStation * model.beam_stations().size() << " of them from output.beam_stations)";
  }
  msg << ": " << samples * per_sample << " values to write, more than " << kMaxOutputValues
      << " (about 1 GB of CSV); expected a lower rate_hz, a shorter t_end, "
      << (model.beam_stations().empty() ? "" : "fewer beam stations, ") << "or output.allow_large_output: true";
  throw ConfigError(msg.str());
}

}  // namespace flexmbd
