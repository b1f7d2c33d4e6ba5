#include "flexmbd/io/config_loader.hpp"

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/initial_placement.hpp"
#include "flexmbd/io/loop_assembly.hpp"
#include "flexmbd/io/loop_closure.hpp"
#include "flexmbd/io/text_file.hpp"
#include "flexmbd/io/urdf_reader.hpp"
#include "flexmbd/io/yaml_document.hpp"
#include "flexmbd/io/yaml_overlay.hpp"
#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {

ModelSpec LoadModelSpec(const std::string& urdf_path, const std::string& yaml_path) {
  const std::string urdf_xml = ReadTextFile(urdf_path, "URDF file");
  const YAML::Node params =
      yaml_path.empty() ? YAML::Node() : io::ParseYamlDocument(ReadTextFile(yaml_path, "YAML file"), yaml_path);
  return LoadModelSpecFromStrings(urdf_xml, urdf_path, params, yaml_path);
}

ModelSpec LoadModelSpecFromStrings(const std::string& urdf_xml, const std::string& urdf_name, const YAML::Node& params,
                                   const std::string& params_name) {
  io::UrdfModel model = io::ReadUrdf(urdf_xml, urdf_name, io::BeamLinkNames(params, params_name), params_name);
  io::ApplyYamlOverlay(params, params_name, &model);
  io::PlaceBodies(model.free_bodies, &model.spec);
  model.spec.source = params_name.empty() ? urdf_name : urdf_name + " + " + params_name;
  io::AssembleLoops(model.free_bodies, &model.spec);
  io::CloseLoops(model.spec.source, &model.spec);
  return model.spec;
}

}  // namespace flexmbd
