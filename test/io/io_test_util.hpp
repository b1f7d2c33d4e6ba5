#pragma once
// Helpers shared by the test/io tests: data paths and ConfigError messages.

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/config_loader.hpp"

namespace flexmbd {
namespace test {

/// Absolute path of a file under test/data.
inline std::string DataPath(const std::string& relative) {
  return std::string(FLEXMBD_SOURCE_DIR) + "/test/data/" + relative;
}

/// The text of a file under test/data ("urdf/pendulum.urdf").
inline std::string ReadDataText(const std::string& relative) {
  std::ifstream file(DataPath(relative));
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/// Loads test/data/urdf/<urdf_file> with inline YAML parameters; messages name the files without folders.
inline ModelSpec LoadDataUrdf(const std::string& urdf_file, const std::string& yaml, const std::string& params_name) {
  return LoadModelSpecFromStrings(ReadDataText("urdf/" + urdf_file), urdf_file, YAML::Load(yaml), params_name);
}

/// A URDF with a 'world' link, one link per name in `links` (1 kg, unit principal moments [kg m^2] at the
/// link origin), and `joints` (XML).
inline std::string WorldUrdf(const std::vector<std::string>& links, const std::string& joints) {
  std::string urdf = "<robot name=\"test\"><link name=\"world\"/>";
  for (const std::string& link : links) {
    urdf += "<link name=\"" + link + "\"><inertial><mass value=\"1\"/>" +
            "<inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link>";
  }
  return urdf + joints + "</robot>";
}

/// WorldUrdf with one link, "link", on a continuous joint "hinge" from the world about `axis` ("0 0 1").
inline std::string HingeUrdf(const std::string& axis) {
  return WorldUrdf({"link"}, "<joint name=\"hinge\" type=\"continuous\"><parent link=\"world\"/>"
                             "<child link=\"link\"/><axis xyz=\"" + axis + "\"/></joint>");
}

/// WorldUrdf with a hinge about y limited to [-0.5, 0.7] rad ("arm"), a continuous hub about z ("hub") and a slide
/// along x limited to [-1, 1] m ("block"), each from the world: joints with and without a URDF <limit>.
inline std::string LimitedJointsUrdf() {
  return WorldUrdf({"arm", "hub", "block"}, R"(
  <joint name="hinge" type="revolute"><parent link="world"/><child link="arm"/><axis xyz="0 1 0"/>
    <limit lower="-0.5" upper="0.7" effort="1" velocity="1"/></joint>
  <joint name="spin" type="continuous"><parent link="world"/><child link="hub"/><axis xyz="0 0 1"/></joint>
  <joint name="slide" type="prismatic"><parent link="world"/><child link="block"/><axis xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>)");
}

/// The message of the ConfigError that `load` throws, or a note that it threw none.
inline std::string ConfigErrorOf(const std::function<void()>& load) {
  try {
    load();
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "(no ConfigError thrown)";
}

/// Loads an inline URDF with inline YAML parameters, named as files in messages.
inline ModelSpec LoadInline(const std::string& urdf, const std::string& yaml,
                            const std::string& urdf_name = "test.urdf", const std::string& params_name = "test.yaml") {
  return LoadModelSpecFromStrings(urdf, urdf_name, YAML::Load(yaml), params_name);
}

}  // namespace test
}  // namespace flexmbd

/// Expects `statement` to throw a ConfigError whose message contains `substring`.
#define EXPECT_CONFIG_ERROR(statement, substring)                                      \
  do {                                                                                 \
    const std::string message_ = ::flexmbd::test::ConfigErrorOf([&]() { statement; }); \
    EXPECT_NE(message_.find(substring), std::string::npos) << "message: " << message_; \
  } while (false)
