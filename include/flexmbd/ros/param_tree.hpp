#pragma once
/// @file
/// Parameter server -> YAML: the node hands the loader the same tree a YAML file gives the runner, so one
/// schema and one parser (flexmbd_io) check both.

#include <xmlrpcpp/XmlRpcValue.h>
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace flexmbd {
namespace ros {

/// The YAML tree of a parameter value: structs become maps, arrays sequences, numbers, booleans and strings
/// scalars (doubles with 17 significant digits, so they parse back exactly). Throws ConfigError naming
/// `name` (the parameter's path) for a date, binary or empty value, which YAML configs never hold.
YAML::Node ToYaml(const XmlRpc::XmlRpcValue& value, const std::string& name);

/// The tree of the struct `value` (a namespace) without its members in `excluded` (the node's own settings).
/// A value that is not a struct (an empty namespace) gives a null node: no extension parameters.
YAML::Node ToYamlWithout(const XmlRpc::XmlRpcValue& value, const std::string& name,
                         const std::vector<std::string>& excluded);

}  // namespace ros
}  // namespace flexmbd
