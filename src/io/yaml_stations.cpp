// `output.beam_stations` and `output.strip_stations`: a name -> stations along a beam, checked against the beams
// read from `beams:` and the strips from `aero.strips`.

#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {
namespace {
// The beam each named entry stands on (a strip's beam, or the beam itself); nullptr for an unknown name.
using BeamOf = const BeamSpec* (*)(const UrdfModel& model, const std::string& name);

const BeamSpec* FindBeam(const UrdfModel& model, const std::string& name) {
  for (const BeamSpec& beam : model.spec.beams) {
    if (beam.name == name) return &beam;
  }
  return nullptr;
}

const BeamSpec* StripBeam(const UrdfModel& model, const std::string& name) {
  for (const AeroStripSpec& strip : model.spec.aero_strips) {
    if (strip.name == name) return FindBeam(model, strip.beam);
  }
  return nullptr;
}

// Reads output.<key>: a map from the names of `kinds` (known: `names`, defined in `where`) to stations in
// [0, beam length].
void ReadStationLists(const Field& output, const UrdfModel& model, const char* key, const char* kind,
                      const char* kinds, const std::string& where, const std::vector<std::string>& names,
                      BeamOf beam_of, std::map<std::string, std::vector<double>>* lists) {
  const Field stations = output.Child(key);
  if (!stations.present()) return;
  for (const std::string& name :
       MapKeys(stations, std::string("a map from ") + kind + " names to lists of stations [m]")) {
    const Field list = stations.Child(name);
    const BeamSpec* beam = beam_of(model, name);
    if (beam == nullptr) list.Fail(NotFoundMessage(kind, kinds, name, where, names));
    const std::vector<double> s = ReadNumberList(list, Quantity{"a distance from the root", Bound::kNonNegative, "m"});
    for (size_t k = 0; k < s.size(); ++k) {
      if (s[k] > beam->length) {
        list.Entry(k).Fail(list.Entry(k).Text() + " is beyond the tip; expected 0 <= s <= " +
                           FormatNumber(beam->length) + " [m] (the length of beam " + beam->name + ")");
      }
    }
    (*lists)[name] = s;
  }
}
}  // namespace

void ReadBeamStations(const Field& output, const UrdfModel& model, OutputSpec* spec) {
  std::vector<std::string> names;
  for (const BeamSpec& beam : model.spec.beams) names.push_back(beam.name);
  ReadStationLists(output, model, "beam_stations", "beam", "beams", model.name, names, FindBeam, &spec->beam_stations);
}

void ReadStripStations(const Field& output, const UrdfModel& model, OutputSpec* spec) {
  std::vector<std::string> names;
  for (const AeroStripSpec& strip : model.spec.aero_strips) names.push_back(strip.name);
  ReadStationLists(output, model, "strip_stations", "strip", "strips", "aero.strips", names, StripBeam,
                   &spec->strip_stations);
}

}  // namespace io
}  // namespace flexmbd
