#pragma once
/// @file
/// A YAML tree as the parameter server holds it after `rosparam load`: the node's view of the same file.

#include <xmlrpcpp/XmlRpcValue.h>
#include <yaml-cpp/yaml.h>

namespace flexmbd {
namespace fuzz {

/// Maps become structs and sequences arrays; a scalar becomes an int if it reads as a 32-bit integer, a double
/// if it reads as a number, a boolean for true/false, text otherwise; an empty value becomes empty text (the
/// parameter server has no null).
XmlRpc::XmlRpcValue ParamTreeFromYaml(const YAML::Node& node);

}  // namespace fuzz
}  // namespace flexmbd
