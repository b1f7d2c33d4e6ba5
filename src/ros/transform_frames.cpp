#include "flexmbd/ros/transform_frames.hpp"

#include <urdf_parser/urdf_parser.h>

#include <map>
#include <optional>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/urdf_pose.hpp"
#include "flexmbd/io/urdf_tree.hpp"

namespace flexmbd {
namespace ros {
namespace {

constexpr char kWorld[] = "world";

// Builds the tree link by link from the URDF root, with a stack of links rather than recursion: a chain may
// be tens of thousands of links deep.
class FrameTreeBuilder {
 public:
  explicit FrameTreeBuilder(const Model& model) {
    for (const BodyInfo& body : model.bodies()) bodies_[body.name] = &body;
    for (const BeamInfo& beam : model.beams()) beams_[beam.name] = &beam;
  }

  FrameTree Build(const urdf::Link& root) {
    const std::optional<FramePlacement> moving_root = MovingPlacement(root.name);
    if (moving_root) {
      tree_.world_frame = kWorld;
      AddMoving(root.name, kWorld, *moving_root, FramePlacement{});
    } else {
      tree_.world_frame = root.name;
      placements_[root.name] = FramePlacement{};
    }
    std::vector<const urdf::Link*> to_visit{&root};
    while (!to_visit.empty()) {
      const urdf::Link& link = *to_visit.back();
      to_visit.pop_back();
      // reversed onto the stack, so that a link's children come out in URDF order
      for (auto child = link.child_links.rbegin(); child != link.child_links.rend(); ++child) {
        AddChild(link.name, **child);
        to_visit.push_back(child->get());
      }
    }
    return std::move(tree_);
  }

 private:
  // The placement of a body's or a beam's link frame; nullopt for a massless link.
  std::optional<FramePlacement> MovingPlacement(const std::string& link) const {
    if (const auto body = bodies_.find(link); body != bodies_.end()) {
      return FramePlacement{body->second->node, Mat3::Identity(), body->second->p_NBo_N};
    }
    if (const auto beam = beams_.find(link); beam != beams_.end()) return FramePlacement{beam->second->nodes.front()};
    return std::nullopt;
  }

  void AddChild(const std::string& parent, const urdf::Link& child) {
    if (const std::optional<FramePlacement> placement = MovingPlacement(child.name)) {
      AddMoving(child.name, parent, *placement, placements_.at(parent));
      return;
    }
    // the loader makes every other link a frame fixed to its parent (urdf_reader.hpp)
    const urdf::Joint& joint = *child.parent_joint;
    FLEXMBD_DEMAND(joint.type == urdf::Joint::FIXED);
    const urdf::Pose& origin = joint.parent_to_joint_origin_transform;
    const StaticFrame frame{child.name, parent, io::ToMat3(origin.rotation), io::ToVec3(origin.position)};
    const FramePlacement& at = placements_.at(parent);
    placements_[child.name] = FramePlacement{at.node, at.R_NF * frame.R_PF, at.p_NF_N + at.R_NF * frame.p_PF};
    tree_.fixed.push_back(frame);
  }

  void AddMoving(const std::string& name, const std::string& parent, const FramePlacement& placement,
                 const FramePlacement& parent_placement) {
    placements_[name] = placement;
    tree_.moving.push_back(TransformFrame{name, parent, placement, parent_placement});
    const auto beam = beams_.find(name);
    if (beam == beams_.end()) return;
    const std::vector<int>& nodes = beam->second->nodes;
    for (size_t k = 0; k < nodes.size(); ++k) {
      tree_.moving.push_back(TransformFrame{BeamNodeFrameName(name, k), name, FramePlacement{nodes[k]}, placement});
    }
  }

  std::map<std::string, const BodyInfo*> bodies_;
  std::map<std::string, const BeamInfo*> beams_;
  std::map<std::string, FramePlacement> placements_;  ///< of every link added so far
  FrameTree tree_;
};

}  // namespace

std::string BeamNodeFrameName(const std::string& beam, size_t k) { return beam + "/node_" + std::to_string(k); }

FrameTree UrdfFrameTree(const std::string& urdf_xml, const Model& model) {
  const io::UrdfTreeOwner urdf(urdf::parseURDF(urdf_xml));
  FLEXMBD_DEMAND(urdf && urdf->getRoot());  // the model was loaded from it
  return FrameTreeBuilder(model).Build(*urdf->getRoot());
}

}  // namespace ros
}  // namespace flexmbd
