#include "flexmbd/ros/world_frame.hpp"

#include <urdf_parser/urdf_parser.h>

#include <algorithm>

#include "flexmbd/io/urdf_tree.hpp"

namespace flexmbd {
namespace ros {

std::string WorldFrameName(const std::string& urdf_xml, const Model& model) {
  const std::string kWorld = "world";
  const io::UrdfTreeOwner urdf(urdf::parseURDF(urdf_xml));
  if (!urdf || !urdf->getRoot()) return kWorld;
  const std::string root = urdf->getRoot()->name;
  const bool root_is_body = std::any_of(model.bodies().begin(), model.bodies().end(),
                                        [&root](const BodyInfo& body) { return body.name == root; });
  return root_is_body ? kWorld : root;
}

}  // namespace ros
}  // namespace flexmbd
