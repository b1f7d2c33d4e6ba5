#pragma once
/// @file
/// YAML extension parameters applied to a model read from a URDF (docs/config.md).

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "flexmbd/io/urdf_reader.hpp"

namespace flexmbd {
namespace io {

/// The top-level keys of the extension parameters: beams, joints, solver, output, loads.
const std::vector<std::string>& YamlSectionNames();

/// Overwrites what `params` gives (joints, solver, output, loads) in `model->spec`; everything else keeps
/// its URDF value or the ModelSpec default. An empty (null) document changes nothing.
/// @throws ConfigError naming `params_name`, the field path, the offending value and the expected form.
void ApplyYamlOverlay(const YAML::Node& params, const std::string& params_name, UrdfModel* model);

}  // namespace io
}  // namespace flexmbd
