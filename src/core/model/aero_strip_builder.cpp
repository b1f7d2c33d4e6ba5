#include "aero_strip_builder.hpp"

#include "flexmbd/common/error.hpp"

namespace flexmbd {

const BeamInfo& StripBeam(const Model& model, const std::string& prefix, const AeroStripSpec& strip) {
  std::string names;
  for (const BeamInfo& beam : model.beams()) {
    if (beam.name == strip.beam) return beam;
    names += (names.empty() ? "" : ", ") + beam.name;
  }
  throw ConfigError(prefix + "aero.strips." + strip.name + ".beam: no beam '" + strip.beam +
                    "'; expected a link under beams: (" + (names.empty() ? "there are none" : names) + ")");
}

std::vector<std::unique_ptr<BeamStripAero>> MakeAeroStrips(const Model& model, const std::string& prefix,
                                                           const AeroStripSpec& strip, const AeroFlowSpec& flow,
                                                           int first_state) {
  const BeamInfo& beam = StripBeam(model, prefix, strip);
  std::vector<std::unique_ptr<BeamStripAero>> strips;
  for (size_t k = 0; k < beam.nodes.size(); ++k) {
    AeroStripSpec node_strip = strip;
    node_strip.name = strip.name + " node " + std::to_string(k);
    const int state = first_state + static_cast<int>(k) * strip.inflow_states;
    strips.push_back(std::make_unique<BeamStripAero>(node_strip, flow, beam.nodes[k],
                                                     model.node_unknown(beam.nodes[k]), beam.lumped_lengths[k],
                                                     model.element_state_unknown(state)));
  }
  return strips;
}

}  // namespace flexmbd
