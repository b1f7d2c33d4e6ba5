#pragma once
/// @file
/// Parses the text of a YAML extension-parameter file into one document (docs/config.md, "Errors").

#include <yaml-cpp/yaml.h>

#include <string>

namespace flexmbd {
namespace io {

/// The one YAML document in `text`; an empty text gives a null node.
/// @param[in] name the file's name in messages
/// @throws ConfigError "<name>: line L, column C: not valid YAML (...)" on a syntax error, "<name>: line L:
///   a second YAML document; expected one document" if the text holds more than one (yaml-cpp would ignore
///   all but the first), and "<name>: <field>: line L, column C: YAML tag '!x' ..." for an explicit tag
///   (the schema fixes every field's type, so a tag could only be ignored).
YAML::Node ParseYamlDocument(const std::string& text, const std::string& name);

}  // namespace io
}  // namespace flexmbd
