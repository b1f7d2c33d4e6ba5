#include "flexmbd/ros/node_case.hpp"

#include <ros/console.h>

#include <algorithm>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/yaml_overlay.hpp"
#include "flexmbd/ros/param_tree.hpp"
#include "flexmbd/io/text_file.hpp"

namespace flexmbd {
namespace ros {
namespace {

constexpr char kRobotDescription[] = "robot_description";

struct UrdfSource {
  std::string xml;
  std::string name;  ///< in messages: the file, or the parameter
};

UrdfSource ReadUrdf(const ::ros::NodeHandle& node, const NodeSettings& settings) {
  if (!settings.urdf_file.empty()) return UrdfSource{ReadTextFile(settings.urdf_file, "URDF file"), settings.urdf_file};
  std::string key;
  std::string xml;
  if (!node.searchParam(kRobotDescription, key) || !node.getParam(key, xml)) {
    throw ConfigError(node.resolveName(kRobotDescription) +
                      ": not set (or not text); expected the URDF document in the robot_description parameter, "
                      "or a URDF file path in ~urdf_file");
  }
  return UrdfSource{xml, key};
}

// A private parameter that is neither a node setting nor a YAML section is refused here, not by the loader,
// whose message would list the sections only: it is as likely a misspelt setting (~realtime_factor).
void CheckPrivateNames(const YAML::Node& params, const std::string& private_namespace) {
  if (!params.IsMap()) return;
  const std::vector<std::string>& sections = io::YamlSectionNames();
  for (const auto& entry : params) {
    const std::string name = entry.first.Scalar();
    if (std::find(sections.begin(), sections.end(), name) != sections.end()) continue;
    std::vector<std::string> known = NodeSettingNames();
    known.insert(known.end(), sections.begin(), sections.end());
    const std::string closest = io::ClosestName(name, known);
    throw ConfigError(private_namespace + "/" + io::QuoteForMessage(name) + ": unknown parameter; " +
                      (closest.empty() ? "" : "did you mean '" + closest + "'? ") +
                      "expected a node setting (" + io::JoinNames(NodeSettingNames()) + ") or a section of the case (" +
                      io::JoinNames(sections) + ", docs/config.md)");
  }
}

YAML::Node ReadExtensionParameters(const ::ros::NodeHandle& private_node) {
  XmlRpc::XmlRpcValue tree;
  if (!private_node.getParam(private_node.getNamespace(), tree)) return YAML::Node();
  std::vector<std::string> not_case = NodeSettingNames();
  not_case.push_back(kRecordedTopicsParam);  // left by an earlier run of the node
  YAML::Node params = ToYamlWithout(tree, private_node.getNamespace(), not_case);
  CheckPrivateNames(params, private_node.getNamespace());
  return params;
}

}  // namespace

NodeCase LoadNodeCase(const ::ros::NodeHandle& node, const ::ros::NodeHandle& private_node) {
  NodeSettings settings = ReadNodeSettings(private_node);
  const UrdfSource urdf = ReadUrdf(node, settings);
  ModelSpec spec =
      LoadModelSpecFromStrings(urdf.xml, urdf.name, ReadExtensionParameters(private_node), private_node.getNamespace());
  for (const std::string& warning : spec.warnings) ROS_WARN_STREAM("flexmbd: " << warning);
  if (spec.solver.analysis == SolverSpec::Analysis::kEigen) {
    throw ConfigError(private_node.getNamespace() +
                      ": solver.analysis: eigen is not a run the node can publish; expected dynamic or static "
                      "(flexmbd_run prints eigen-analyses)");
  }
  if (!spec.solver.eigen.at_times.empty()) {
    throw ConfigError(private_node.getNamespace() +
                      ": solver.eigen.at_times: the node publishes no mode tables; expected no at_times "
                      "(flexmbd_run prints them)");
  }
  if (settings.rate_hz) spec.output.rate_hz = *settings.rate_hz;
  // the node's ~bag counts in BuildModel's bound on the output size
  if (settings.bag) spec.output.bag = *settings.bag;
  RecordingFiles files{spec.output.bag, settings.bag_compression, spec.output.csv};
  Model model = BuildModel(spec);
  FrameTree frames = UrdfFrameTree(urdf.xml, model);
  return NodeCase{std::move(settings), std::move(model), std::move(frames), std::move(files)};
}

}  // namespace ros
}  // namespace flexmbd
