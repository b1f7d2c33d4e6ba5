// `output.beam_stations`: beam name -> stations along it, checked against the beams read from `beams:`.

#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {

void ReadBeamStations(const Field& output, const UrdfModel& model, OutputSpec* spec) {
  const Field stations = output.Child("beam_stations");
  if (!stations.present()) return;
  std::vector<std::string> names;
  for (const BeamSpec& beam : model.spec.beams) names.push_back(beam.name);
  for (const std::string& name : MapKeys(stations, "a map from beam names to lists of stations [m]")) {
    const Field list = stations.Child(name);
    const BeamSpec* beam = nullptr;
    for (const BeamSpec& candidate : model.spec.beams) {
      if (candidate.name == name) beam = &candidate;
    }
    if (beam == nullptr) list.Fail(NotFoundMessage("beam", "beams", name, model.name, names));
    const std::vector<double> s = ReadNumberList(list, Quantity{"a distance from the root", Bound::kNonNegative, "m"});
    for (size_t k = 0; k < s.size(); ++k) {
      if (s[k] > beam->length) {
        list.Entry(k).Fail(list.Entry(k).Text() + " is beyond the tip; expected 0 <= s <= " +
                           FormatNumber(beam->length) + " [m] (the beam length)");
      }
    }
    spec->beam_stations[name] = s;
  }
}

}  // namespace io
}  // namespace flexmbd
