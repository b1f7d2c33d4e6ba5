#pragma once
/// @file
/// Mutations of a config file's text that no tree can express: a file cut short, a line lost, a second YAML
/// document, an explicit YAML tag.

#include <string>

#include "hostile_values.hpp"

namespace flexmbd {
namespace fuzz {

/// Applies one text mutation to `text` in place; `yaml` allows the YAML-only ones (a second document, a tag).
void MutateText(std::string* text, bool yaml, Rng* rng);

}  // namespace fuzz
}  // namespace flexmbd
