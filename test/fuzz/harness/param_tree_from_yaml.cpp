#include "param_tree_from_yaml.hpp"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <string>

namespace flexmbd {
namespace fuzz {
namespace {

XmlRpc::XmlRpcValue ScalarValue(const std::string& text) {
  if (text.empty()) return XmlRpc::XmlRpcValue(std::string());
  char* end = nullptr;
  errno = 0;
  const long integer = std::strtol(text.c_str(), &end, 10);
  if (*end == '\0' && errno == 0 && integer >= INT_MIN && integer <= INT_MAX) {
    return XmlRpc::XmlRpcValue(static_cast<int>(integer));
  }
  const double number = std::strtod(text.c_str(), &end);
  if (*end == '\0') return XmlRpc::XmlRpcValue(number);
  if (text == "true" || text == "false") return XmlRpc::XmlRpcValue(text == "true");
  return XmlRpc::XmlRpcValue(text);
}

}  // namespace

XmlRpc::XmlRpcValue ParamTreeFromYaml(const YAML::Node& node) {
  XmlRpc::XmlRpcValue value;
  if (node.IsMap()) {
    value.begin();  // an empty struct, not an invalid value, when the map is empty
    for (auto entry : node) value[entry.first.Scalar()] = ParamTreeFromYaml(entry.second);
  } else if (node.IsSequence()) {
    value.setSize(static_cast<int>(node.size()));
    for (size_t k = 0; k < node.size(); ++k) value[static_cast<int>(k)] = ParamTreeFromYaml(node[k]);
  } else {
    value = ScalarValue(node.IsScalar() ? node.Scalar() : std::string());
  }
  return value;
}

}  // namespace fuzz
}  // namespace flexmbd
