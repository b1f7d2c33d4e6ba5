#pragma once
/// @file
/// Loads a mechanism from a URDF and optional YAML extension parameters into a ModelSpec
/// (docs/config.md). One schema and one parser serve the runner (files) and the ROS node (the parameter
/// tree converted to a YAML::Node).
///
/// @code
///   const flexmbd::ModelSpec spec = flexmbd::LoadModelSpec("config/pendulum.urdf", "config/pendulum.yaml");
/// @endcode

#include <yaml-cpp/yaml.h>

#include <string>

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

/// Reads and loads a URDF file and a YAML file of extension parameters.
/// @param[in] urdf_path path of the URDF file
/// @param[in] yaml_path path of the YAML file; "" loads the URDF alone (ModelSpec defaults elsewhere)
/// @throws ConfigError "cannot open ..." if a file cannot be read, "cannot read ...: it is a directory" if
///   it is not a text file (text_file.hpp), the errors of ParseYamlDocument (a syntax error, a second
///   document, a tag; yaml_document.hpp), and every error of LoadModelSpecFromStrings.
ModelSpec LoadModelSpec(const std::string& urdf_path, const std::string& yaml_path);

/// Loads a URDF document and a YAML tree of extension parameters.
/// @param[in] urdf_xml the URDF document
/// @param[in] urdf_name its name in messages (a file name, or "robot_description")
/// @param[in] params the extension parameters; a null node loads the URDF alone
/// @param[in] params_name their name in messages (a file name, or the parameter namespace)
/// @return the model: bodies placed by forward kinematics at the joints' initial motion, joints, loads,
///   solver and output settings; `source` is "<urdf_name> + <params_name>".
/// @throws ConfigError with a one-line message naming the file, the field path, the offending value and
///   the expected form.
ModelSpec LoadModelSpecFromStrings(const std::string& urdf_xml, const std::string& urdf_name, const YAML::Node& params,
                                   const std::string& params_name);

}  // namespace flexmbd
