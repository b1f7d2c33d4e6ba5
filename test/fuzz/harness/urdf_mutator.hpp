#pragma once
/// @file
/// Structure-aware mutation of a URDF document: the text stays XML and mostly a robot, so urdfdom accepts it
/// and the reader's own checks (topology, inertia, joint kinds, names) are reached.

#include <tinyxml2.h>

#include <memory>
#include <string>
#include <vector>

#include "hostile_values.hpp"

namespace flexmbd {
namespace fuzz {

class UrdfMutator {
 public:
  /// @param[in] donors the seed URDF texts: links and joints to graft into another robot
  explicit UrdfMutator(const std::vector<std::string>& donors);

  /// Applies one mutation to `doc` in place: a hostile number in an attribute (one entry of "x y z"), an
  /// entry dropped or added, another joint type, a parent or child link rewired (a cycle, a second parent, an
  /// unknown link), an element deleted or duplicated, a name changed (a duplicate, a comma), an attribute
  /// deleted, or a link or joint grafted from a donor.
  void Mutate(tinyxml2::XMLDocument* doc, Rng* rng) const;

 private:
  std::vector<std::unique_ptr<tinyxml2::XMLDocument>> donors_;
};

/// The document as XML text.
std::string PrintXml(const tinyxml2::XMLDocument& doc);

}  // namespace fuzz
}  // namespace flexmbd
