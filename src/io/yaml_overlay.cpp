#include "flexmbd/io/yaml_overlay.hpp"

#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {

const std::vector<std::string>& YamlSectionNames() {
  static const std::vector<std::string> names{"beams", "joints", "solver", "output", "loads", "aero", "closures"};
  return names;
}

void ApplyYamlOverlay(const YAML::Node& params, const std::string& params_name, UrdfModel* model) {
  const Field root(params, params_name);
  CheckKeys(root, YamlSectionNames());
  ReadBeams(root.Child("beams"), model);
  ReadSolver(root.Child("solver"), &model->spec.solver);  // t_end bounds the drives' paths (ReadJoints)
  ReadClosures(root.Child("closures"), model);
  ReadJoints(root.Child("joints"), model);
  ReadOutput(root.Child("output"), model->spec.solver.t_end, &model->spec.output);
  ReadBeamStations(root.Child("output"), *model, &model->spec.output);
  ReadLoads(root.Child("loads"), *model, &model->spec.loads);
  ReadAero(root.Child("aero"), model);
  ReadStripStations(root.Child("output"), *model, &model->spec.output);
  CheckAirspeedSweep(root, model->spec);
  CheckStaticStart(root, model->spec);
}

}  // namespace io
}  // namespace flexmbd
