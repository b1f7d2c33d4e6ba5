#pragma once
// BuildModel's helper for `aero.sections` (docs/config.md, "aero"): the element of one typical section.

#include <memory>
#include <string>

#include "flexmbd/aero/typical_section_aero.hpp"
#include "flexmbd/model/model.hpp"

namespace flexmbd {

/// The aerodynamic element of `section` on the joints it names, its first inflow state at `first_state`.
/// Throws ConfigError (after `prefix`, the source) for a joint that does not exist, is of the wrong type or does
/// not move along (plunge: z) or about (pitch, flap: y) the axis the section's loads assume.
std::unique_ptr<TypicalSectionAero> MakeAeroSection(const Model& model, const std::string& prefix,
                                                    const AeroSectionSpec& section, int first_state);

}  // namespace flexmbd
