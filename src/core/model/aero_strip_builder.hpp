#pragma once
// BuildModel's helper for `aero.strips` (docs/config.md, "aero"): one strip element per node of the beam.

#include <memory>
#include <string>
#include <vector>

#include "flexmbd/aero/beam_strip_aero.hpp"
#include "flexmbd/model/model.hpp"

namespace flexmbd {

/// The beam that `strip` names; throws ConfigError (after `prefix`, the source) if there is none.
const BeamInfo& StripBeam(const Model& model, const std::string& prefix, const AeroStripSpec& strip);

/// The strips of `strip` on every node of its beam, root to tip, over the nodes' lumped lengths; the first
/// one's inflow states start at `first_state`, each strip owning strip.inflow_states; on `rotor`'s blade if it
/// has one.
std::vector<std::unique_ptr<BeamStripAero>> MakeAeroStrips(const Model& model, const std::string& prefix,
                                                           const AeroStripSpec& strip, const AeroFlowSpec& flow,
                                                           int first_state, const StripRotor& rotor);

/// The rotor of each strip of spec.aero_strips (in that order; no rotor where index < 0), the rotors' inflows
/// numbered from `first_state` in spec.aero_rotors' order. Throws ConfigError (after `prefix`) for a rotor naming
/// a strip that is not under aero.strips or that another rotor already has.
std::vector<StripRotor> StripRotors(const Model& model, const std::string& prefix, const ModelSpec& spec,
                                    int first_state);

/// The stations of output.strip_stations on the strips of `model` (model.aero_strips() built); throws ConfigError
/// (after `prefix`) for a name that is not under aero.strips or a station off its beam.
std::vector<StripStationInfo> LocateStripStations(const Model& model, const std::string& prefix, const ModelSpec& spec);

}  // namespace flexmbd
