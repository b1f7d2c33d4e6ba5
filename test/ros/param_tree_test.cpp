// Parameter server -> YAML (include/flexmbd/ros/param_tree.hpp): the node's parameters reach the loader as
// the same tree a YAML file gives the runner.

#include "flexmbd/ros/param_tree.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/io/text_file.hpp"
#include "ros_test_util.hpp"

namespace flexmbd {
namespace ros {
namespace param_tree_test {

// What `rosparam load` puts on the parameter server for a YAML scalar: Python's YAML types it as an int, a
// float, a bool or a string.
XmlRpc::XmlRpcValue RosparamValue(const YAML::Node& node) {
  if (node.IsMap()) {
    XmlRpc::XmlRpcValue value;
    for (const auto& member : node) value[member.first.as<std::string>()] = RosparamValue(member.second);
    return value;
  }
  if (node.IsSequence()) {
    XmlRpc::XmlRpcValue value;
    value.setSize(static_cast<int>(node.size()));
    for (size_t k = 0; k < node.size(); ++k) value[static_cast<int>(k)] = RosparamValue(node[k]);
    return value;
  }
  const std::string text = node.Scalar();
  if (text == "true" || text == "false") return XmlRpc::XmlRpcValue(text == "true");
  std::istringstream as_int(text);
  int integer = 0;
  if (as_int >> integer && as_int.eof()) return XmlRpc::XmlRpcValue(integer);
  std::istringstream as_double(text);
  double number = 0.0;
  if (as_double >> number && as_double.eof()) return XmlRpc::XmlRpcValue(number);
  return XmlRpc::XmlRpcValue(text);
}

TEST(ParamTree, ScalarsKeepTheirValues) {
  // 0.1 has no short exact decimal form: 17 significant digits bring back the same double.
  XmlRpc::XmlRpcValue value;
  value["ratio"] = 0.1;
  value["count"] = 7;
  value["on"] = true;
  value["name"] = "lz4";
  value["list"][0] = 1.0e-7;
  const YAML::Node tree = ToYaml(value, "/node");
  EXPECT_EQ(tree["ratio"].as<double>(), 0.1);
  EXPECT_EQ(tree["count"].as<int>(), 7);
  EXPECT_TRUE(tree["on"].as<bool>());
  EXPECT_EQ(tree["name"].as<std::string>(), "lz4");
  ASSERT_TRUE(tree["list"].IsSequence());
  EXPECT_EQ(tree["list"][0].as<double>(), 1.0e-7);
}

TEST(ParamTree, ExcludedMembersAreLeftOut) {
  XmlRpc::XmlRpcValue value;
  value["solver"]["t_end"] = 2.0;
  value["bag"] = "run.bag";
  const YAML::Node tree = ToYamlWithout(value, "/node", {"bag", "publish"});
  EXPECT_TRUE(tree["solver"].IsMap());
  EXPECT_FALSE(tree["bag"]);
}

TEST(ParamTree, EmptyNamespaceGivesNoParameters) {
  EXPECT_TRUE(ToYamlWithout(XmlRpc::XmlRpcValue(), "/node", {}).IsNull());
}

TEST(ParamTree, DateValueIsAConfigErrorNamingTheParameter) {
  struct tm date = {};
  XmlRpc::XmlRpcValue value;
  value["when"] = XmlRpc::XmlRpcValue(&date);
  try {
    ToYaml(value, "/node");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()),
              "/node/when: a date, binary or empty value; expected numbers, text, booleans, lists and maps");
  }
}

TEST(ParamTree, CaseFromTheParameterServerLoadsAsFromItsFile) {
  // Reference: LoadModelSpec on config/double_pendulum/ (the runner's path). The same YAML, typed as rosparam
  // types it and converted back, must give the same model: one schema, one parser.
  const std::string urdf = test::SourcePath("config/double_pendulum/double_pendulum.urdf");
  const std::string yaml = test::SourcePath("config/double_pendulum/double_pendulum.yaml");
  const ModelSpec from_file = LoadModelSpec(urdf, yaml);
  const YAML::Node params = ToYaml(RosparamValue(YAML::LoadFile(yaml)), "/flexmbd");
  const ModelSpec from_server = LoadModelSpecFromStrings(ReadTextFile(urdf, "URDF file"), urdf, params, "/flexmbd");
  ASSERT_EQ(from_server.joints.size(), from_file.joints.size());
  for (size_t k = 0; k < from_file.joints.size(); ++k) {
    EXPECT_EQ(from_server.joints[k].initial_position, from_file.joints[k].initial_position);
    ASSERT_EQ(from_server.joints[k].effects.size(), from_file.joints[k].effects.size());
    for (size_t v = 0; v < from_file.joints[k].effects.size(); ++v) {
      const VariableEffectsSpec& a = from_server.joints[k].effects[v];
      const VariableEffectsSpec& b = from_file.joints[k].effects[v];
      ASSERT_EQ(a.springs.size(), b.springs.size());
      for (size_t s = 0; s < a.springs.size(); ++s) EXPECT_EQ(a.springs[s].stiffness, b.springs[s].stiffness);
      ASSERT_EQ(a.drives.size(), b.drives.size());
      for (size_t d = 0; d < a.drives.size(); ++d) EXPECT_EQ(a.drives[d].value, b.drives[d].value);
    }
  }
  EXPECT_EQ(from_server.solver.t_end, from_file.solver.t_end);
  EXPECT_EQ(from_server.solver.dt, from_file.solver.dt);
  EXPECT_EQ(from_server.solver.error_tol, from_file.solver.error_tol);
  EXPECT_EQ(from_server.solver.gravity, from_file.solver.gravity);
  EXPECT_EQ(from_server.output.rate_hz, from_file.output.rate_hz);
}

TEST(ParamTree, BadParameterGivesTheLoadersMessageNamingTheNamespace) {
  // Reference: docs/config.md, "Errors": the same message as from a file, with the namespace as its source.
  XmlRpc::XmlRpcValue value;
  value["joints"]["elbow"]["spring"]["k"] = -3.0;
  const std::string urdf = test::SourcePath("config/double_pendulum/double_pendulum.urdf");
  try {
    LoadModelSpecFromStrings(ReadTextFile(urdf, "URDF file"), urdf, ToYaml(value, "/arm"), "/arm");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& error) {
    EXPECT_EQ(std::string(error.what()),
              "/arm: joints.elbow.spring.k: -3 is negative; expected a stiffness >= 0 [N m/rad]");
  }
}

}  // namespace param_tree_test
}  // namespace ros
}  // namespace flexmbd
