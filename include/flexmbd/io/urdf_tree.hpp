#pragma once
/// @file
/// Checks on the structure of a URDF that urdfdom leaves to its user (docs/config.md, "URDF mapping").
/// urdfdom rejects a joint naming a missing link, two parentless links and a URDF with no parentless link,
/// but keeps a link with two parent joints (only the last one read is its parent) and keeps a cycle of
/// joints apart from the root (its links are never reached from the root).

#include <urdf_model/model.h>
#include <urdf_world/types.h>

#include <string>

namespace flexmbd {
namespace io {

/// Why `name` cannot head a CSV column (the CSV header is "joint.<name>.position,..."): "a comma", ...; "" if
/// it can.
std::string CsvNameProblem(const std::string& name);

/// Checks that every link and joint name can head a CSV column (no comma, double quote or control
/// character), that each link is the child of at most one joint, and that every link is reached from the
/// root (so the joints have no cycle). Iterative: a chain of any depth is checked without recursion.
/// @throws ConfigError naming `urdf_name`, the link or joint, and what was expected.
void CheckUrdfTree(const urdf::ModelInterface& urdf, const std::string& urdf_name);

/// Owns a parsed URDF and empties every link's lists of children before it is destroyed: urdfdom links
/// own their children, so destroying a chain of tens of thousands of links would recurse once per link
/// and overflow the stack, and a cycle of links would never be freed.
class UrdfTreeOwner {
 public:
  explicit UrdfTreeOwner(urdf::ModelInterfaceSharedPtr urdf) : urdf_(std::move(urdf)) {}
  ~UrdfTreeOwner();
  UrdfTreeOwner(const UrdfTreeOwner&) = delete;
  UrdfTreeOwner& operator=(const UrdfTreeOwner&) = delete;

  /// False if urdfdom returned no model.
  explicit operator bool() const { return urdf_ != nullptr; }
  const urdf::ModelInterface& operator*() const { return *urdf_; }
  const urdf::ModelInterface* operator->() const { return urdf_.get(); }

 private:
  urdf::ModelInterfaceSharedPtr urdf_;
};

}  // namespace io
}  // namespace flexmbd
