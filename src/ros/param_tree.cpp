#include "flexmbd/ros/param_tree.hpp"

#include <algorithm>
#include <iomanip>
#include <limits>
#include <sstream>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace ros {
namespace {

std::string FormatDouble(double value) {
  std::ostringstream text;
  text << std::setprecision(std::numeric_limits<double>::max_digits10) << value;
  return text.str();
}

YAML::Node StructToYaml(const XmlRpc::XmlRpcValue& value, const std::string& name,
                        const std::vector<std::string>& excluded) {
  YAML::Node map(YAML::NodeType::Map);
  for (const auto& [key, member] : value) {
    if (std::find(excluded.begin(), excluded.end(), key) == excluded.end()) {
      map[key] = ToYaml(member, name + "/" + key);
    }
  }
  return map;
}

}  // namespace

YAML::Node ToYaml(const XmlRpc::XmlRpcValue& value, const std::string& name) {
  using Value = XmlRpc::XmlRpcValue;
  switch (value.getType()) {
    case Value::TypeBoolean:
      return YAML::Node(static_cast<const bool&>(value) ? "true" : "false");
    case Value::TypeInt:
      return YAML::Node(std::to_string(static_cast<const int&>(value)));
    case Value::TypeDouble:
      return YAML::Node(FormatDouble(static_cast<const double&>(value)));
    case Value::TypeString:
      return YAML::Node(static_cast<const std::string&>(value));
    case Value::TypeArray: {
      YAML::Node sequence(YAML::NodeType::Sequence);
      for (int k = 0; k < value.size(); ++k) {
        sequence.push_back(ToYaml(value[k], name + "[" + std::to_string(k) + "]"));
      }
      return sequence;
    }
    case Value::TypeStruct:
      return StructToYaml(value, name, {});
    default:
      break;
  }
  throw ConfigError(name + ": a date, binary or empty value; expected numbers, text, booleans, lists and maps");
}

YAML::Node ToYamlWithout(const XmlRpc::XmlRpcValue& value, const std::string& name,
                         const std::vector<std::string>& excluded) {
  if (value.getType() != XmlRpc::XmlRpcValue::TypeStruct) return YAML::Node();
  return StructToYaml(value, name, excluded);
}

}  // namespace ros
}  // namespace flexmbd
