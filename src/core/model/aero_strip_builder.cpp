#include "aero_strip_builder.hpp"

#include <algorithm>
#include <cmath>

#include "flexmbd/aero/rotor_inflow.hpp"
#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace {
// A flap node stands at a strip's station when their distance along the strip's beam axis is below this share of
// the beam's length, and on the hinge line when its offset from the line b (c - a) aft of the axis along the chord
// is below this share of the semichord: positions written to six figures are.
constexpr double kSameStation = 1.0e-6, kOnHinge = 1.0e-3;
// A blade's node stands within the disc when its distance from the shaft axis exceeds the radius by less than this
// share of it: a tip written to six figures at the radius does.
constexpr double kWithinDisc = 1.0e-6;

const BeamInfo& FindBeam(const Model& model, const std::string& name, const std::string& field) {
  std::string names;
  for (const BeamInfo& beam : model.beams()) {
    if (beam.name == name) return beam;
    names += (names.empty() ? "" : ", ") + beam.name;
  }
  throw ConfigError(field + ": no beam '" + name + "'; expected a link under beams: (" +
                    (names.empty() ? "there are none" : names) + ")");
}

// The flap of each strip of `beam` (docs/theory.md, (A10)): the flap beam's node at the strip's station, over the
// share of the strip's length that the flap node's lumped length covers.
std::vector<StripFlap> StripFlaps(const Model& model, const std::string& prefix, const AeroStripSpec& strip,
                                  const BeamInfo& beam) {
  std::vector<StripFlap> flaps(beam.nodes.size());
  if (strip.flap.beam.empty()) return flaps;
  const std::string field = prefix + "aero.strips." + strip.name + ".flap.beam";
  const BeamInfo& flap = FindBeam(model, strip.flap.beam, field);
  if (&flap == &beam) throw ConfigError(field + ": '" + flap.name + "' is the strips' own beam; expected another beam");
  const std::vector<NodeState>& nodes = model.initial_state().nodes;
  const double hinge = strip.semichord * (strip.flap.c - strip.a);
  for (size_t j = 0; j < flap.nodes.size(); ++j) {
    const NodeState& at = nodes[flap.nodes[j]];
    size_t k = 0;
    double nearest = INFINITY;
    for (size_t i = 0; i < beam.nodes.size(); ++i) {
      const NodeState& n = nodes[beam.nodes[i]];
      const double along = std::abs((at.x - n.x).dot(n.R.col(0)));
      if (along < nearest) nearest = along, k = i;
    }
    const NodeState& n = nodes[beam.nodes[k]];
    const Vec3 offset = n.R.transpose() * (at.x - n.x);
    if (nearest > kSameStation * beam.stations.back()) {
      throw ConfigError(field + ": node " + std::to_string(j) + " of '" + flap.name + "' is " +
                        std::to_string(nearest) + " m along the span from the nearest node of '" + beam.name +
                        "'; expected the flap beam's nodes at stations of the strips' nodes");
    }
    if (std::abs(offset.dot(strip.chord_axis) - hinge) > kOnHinge * strip.semichord ||
        std::abs(offset.dot(strip.normal_axis)) > kOnHinge * strip.semichord) {
      throw ConfigError(field + ": node " + std::to_string(j) + " of '" + flap.name + "' stands " +
                        std::to_string(offset.dot(strip.chord_axis)) + " m aft of and " +
                        std::to_string(offset.dot(strip.normal_axis)) + " m above the axis of '" + beam.name +
                        "'; expected it on the hinge line, b (c - a) = " + std::to_string(hinge) + " m aft");
    }
    if (flaps[k].node >= 0) {
      throw ConfigError(field + ": two nodes of '" + flap.name + "' stand at node " + std::to_string(k) + " of '" +
                        beam.name + "'; expected one flap node per strip");
    }
    flaps[k].node = flap.nodes[j];
    flaps[k].node_unknown = model.node_unknown(flap.nodes[j]);
    flaps[k].fraction = std::min(1.0, flap.lumped_lengths[j] / beam.lumped_lengths[k]);
    flaps[k].R_rest = at.R.transpose() * n.R;
  }
  return flaps;
}

// The rotor's disc reaches every node of a blade (docs/theory.md, (A14)): the harmonics weigh a strip by its place
// relative to the centre, and the centre's component along the axis does not count, so a centre off the shaft axis
// (or a radius short of the tips) shows as a node farther from the axis through the centre than the radius.
void CheckBladeWithinDisc(const Model& model, const std::string& prefix, const AeroRotorSpec& rotor,
                          const AeroStripSpec& strip) {
  const BeamInfo& beam = StripBeam(model, prefix, strip);
  for (size_t k = 0; k < beam.nodes.size(); ++k) {
    const Vec3 offset = model.initial_state().nodes[beam.nodes[k]].x - rotor.center;
    const double distance = (offset - offset.dot(rotor.axis) * rotor.axis).norm();
    if (distance > (1.0 + kWithinDisc) * rotor.radius) {
      const Vec3& c = rotor.center;
      throw ConfigError(prefix + "aero.rotors." + rotor.name + ".center: [" + std::to_string(c.x()) + ", " +
                        std::to_string(c.y()) + ", " + std::to_string(c.z()) + "] leaves node " + std::to_string(k) +
                        " of strip '" + strip.name + "' " + std::to_string(distance) +
                        " m from the shaft axis through it, beyond the radius " + std::to_string(rotor.radius) +
                        " m; expected the disc's centre on the shaft axis (the hub's), every blade node within the "
                        "radius of it");
    }
  }
}
}  // namespace

const BeamInfo& StripBeam(const Model& model, const std::string& prefix, const AeroStripSpec& strip) {
  return FindBeam(model, strip.beam, prefix + "aero.strips." + strip.name + ".beam");
}

std::vector<std::unique_ptr<BeamStripAero>> MakeAeroStrips(const Model& model, const std::string& prefix,
                                                           const AeroStripSpec& strip, const AeroFlowSpec& flow,
                                                           int first_state, const StripRotor& rotor) {
  const BeamInfo& beam = StripBeam(model, prefix, strip);
  const std::vector<StripFlap> flaps = StripFlaps(model, prefix, strip, beam);
  std::vector<std::unique_ptr<BeamStripAero>> strips;
  for (size_t k = 0; k < beam.nodes.size(); ++k) {
    AeroStripSpec node_strip = strip;
    node_strip.name = strip.name + " node " + std::to_string(k);
    const int state = first_state + static_cast<int>(k) * strip.inflow_states;
    strips.push_back(std::make_unique<BeamStripAero>(node_strip, flow, beam.nodes[k],
                                                     model.node_unknown(beam.nodes[k]), beam.lumped_lengths[k],
                                                     model.element_state_unknown(state), flaps[k], rotor));
  }
  return strips;
}

std::vector<StripRotor> StripRotors(const Model& model, const std::string& prefix, const ModelSpec& spec,
                                    int first_state) {
  std::vector<StripRotor> rotors(spec.aero_strips.size());
  std::vector<std::string> owner(spec.aero_strips.size());
  int state = first_state;
  for (size_t r = 0; r < spec.aero_rotors.size(); ++r) {
    const AeroRotorSpec& rotor = spec.aero_rotors[r];
    StripRotor blade;
    blade.index = static_cast<int>(r);
    blade.state = state;
    blade.unknown = model.element_state_unknown(state);
    blade.num_states = RotorInflowStates(rotor);
    blade.axis = rotor.axis;
    blade.center = rotor.center;
    const std::pair<Vec3, Vec3> disc = DiscAxes(rotor.axis);
    blade.harmonic_weights << disc.first / rotor.radius, disc.second / rotor.radius;
    state += blade.num_states;
    for (size_t k = 0; k < rotor.strips.size(); ++k) {
      const std::string field = prefix + "aero.rotors." + rotor.name + ".strips[" + std::to_string(k) + "]";
      const auto strip = std::find_if(spec.aero_strips.begin(), spec.aero_strips.end(),
                                      [&](const AeroStripSpec& s) { return s.name == rotor.strips[k]; });
      if (strip == spec.aero_strips.end()) {
        throw ConfigError(field + ": no strip '" + rotor.strips[k] + "'; expected a name under aero.strips");
      }
      const size_t index = strip - spec.aero_strips.begin();
      if (!owner[index].empty()) {
        throw ConfigError(field + ": strip '" + rotor.strips[k] + "' is already a blade of rotor '" + owner[index] +
                          "'; expected each strip on one rotor at most");
      }
      CheckBladeWithinDisc(model, prefix, rotor, *strip);
      owner[index] = rotor.name;
      rotors[index] = blade;
    }
  }
  return rotors;
}

std::vector<StripStationInfo> LocateStripStations(const Model& model, const std::string& prefix,
                                                  const ModelSpec& spec) {
  std::vector<StripStationInfo> located;
  for (const auto& [name, stations] : spec.output.strip_stations) {
    const std::string field = prefix + "output.strip_stations." + name;
    size_t first = 0;  // the strip's first element in model.aero_strips(): the strips before it, node by node
    auto strip = spec.aero_strips.begin();
    for (; strip != spec.aero_strips.end() && strip->name != name; ++strip) {
      first += StripBeam(model, prefix, *strip).nodes.size();
    }
    if (strip == spec.aero_strips.end()) {
      throw ConfigError(field + ": no strip '" + name + "'; expected a name under aero.strips");
    }
    const BeamInfo& beam = StripBeam(model, prefix, *strip);
    const double length = std::find_if(spec.beams.begin(), spec.beams.end(),
                                       [&](const BeamSpec& b) { return b.name == beam.name; })->length;
    for (size_t k = 0; k < stations.size(); ++k) {
      if (!(stations[k] >= 0.0 && stations[k] <= length)) {
        throw ConfigError(field + "[" + std::to_string(k) + "]: " + std::to_string(stations[k]) +
                          " is off the beam; expected 0 <= s <= " + std::to_string(length) +
                          " [m] (distance from the root)");
      }
      const double s = std::min(stations[k], beam.stations.back());  // the last node's station may round below
      // The last node at or root-side of s; a station on the tip node takes that node alone.
      const size_t node = std::upper_bound(beam.stations.begin(), beam.stations.end(), s) - beam.stations.begin() - 1;
      const size_t next = std::min(node + 1, beam.stations.size() - 1);
      const double span = beam.stations[next] - beam.stations[node];
      located.push_back({name, static_cast<int>(k), s, model.aero_strips()[first + node],
                         model.aero_strips()[first + next], span > 0.0 ? (s - beam.stations[node]) / span : 0.0});
    }
  }
  return located;
}

}  // namespace flexmbd
