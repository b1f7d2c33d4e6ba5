#include "flexmbd/ros/message_conversions.hpp"

#include <Eigen/Geometry>

namespace flexmbd {
namespace ros {
namespace {

// Marker sizes relative to the model's length scale (its largest node distance from the origin).
constexpr double kComSphereDiameter = 0.06;
constexpr double kStickWidth = 0.015;

geometry_msgs::Vector3 ToVector3(const Vec3& v) {
  geometry_msgs::Vector3 out;
  out.x = v.x();
  out.y = v.y();
  out.z = v.z();
  return out;
}

geometry_msgs::Point ToPoint(const Vec3& v) {
  geometry_msgs::Point out;
  out.x = v.x();
  out.y = v.y();
  out.z = v.z();
  return out;
}

std::vector<double> ToVector(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

visualization_msgs::Marker BodyMarker(const BodyInfo& body, int id, int type) {
  visualization_msgs::Marker marker;
  marker.header.frame_id = body.name;
  marker.ns = "bodies";
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.frame_locked = true;
  marker.color.r = 0.2f;
  marker.color.g = 0.5f;
  marker.color.b = 0.9f;
  marker.color.a = 1.0f;
  return marker;
}

}  // namespace

::ros::Time ToStamp(double t) { return ::ros::Time(t); }

sensor_msgs::JointState ToJointState(const Model& model, const OutputSample& sample) {
  sensor_msgs::JointState msg;
  msg.header.stamp = ToStamp(sample.t);
  msg.name = model.variable_names();
  msg.position = ToVector(sample.position);
  msg.velocity = ToVector(sample.velocity);
  msg.effort = ToVector(sample.effort);
  return msg;
}

Energy ToEnergy(const OutputSample& sample) {
  Energy msg;
  msg.header.stamp = ToStamp(sample.t);
  msg.kinetic = sample.kinetic;
  msg.potential = sample.potential;
  msg.external_work = sample.external_work;
  msg.dissipated = sample.dissipated;
  msg.numerical_dissipation = sample.numerical_dissipation;
  return msg;
}

JointReactions ToJointReactions(const Model& model, const OutputSample& sample) {
  JointReactions msg;
  msg.header.stamp = ToStamp(sample.t);
  msg.name.reserve(model.joints().size());
  msg.force.reserve(model.joints().size());
  msg.moment.reserve(model.joints().size());
  for (size_t k = 0; k < model.joints().size(); ++k) {
    msg.name.push_back(model.joints()[k]->name());
    msg.force.push_back(ToVector3(sample.reaction_force_W[k]));
    msg.moment.push_back(ToVector3(sample.reaction_moment[k]));
  }
  return msg;
}

SolverStep ToSolverStep(const OutputSample& sample) {
  SolverStep msg;
  msg.header.stamp = ToStamp(sample.t);
  msg.dt = sample.dt;
  msg.iterations = sample.iterations;
  return msg;
}

tf2_msgs::TFMessage ToLinkTransforms(const Model& model, const State& state, const std::string& world_frame) {
  tf2_msgs::TFMessage msg;
  const ::ros::Time stamp = ToStamp(state.t);
  msg.transforms.reserve(model.bodies().size());
  for (const BodyInfo& body : model.bodies()) {
    const NodeState& node = state.nodes[body.node];
    const Vec3 p_WB = node.x + node.R * body.p_NBo_N;
    const Eigen::Quaterniond q_WB(node.R);
    geometry_msgs::TransformStamped transform;
    transform.header.stamp = stamp;
    transform.header.frame_id = world_frame;
    transform.child_frame_id = body.name;
    transform.transform.translation = ToVector3(p_WB);
    transform.transform.rotation.x = q_WB.x();
    transform.transform.rotation.y = q_WB.y();
    transform.transform.rotation.z = q_WB.z();
    transform.transform.rotation.w = q_WB.w();
    msg.transforms.push_back(transform);
  }
  return msg;
}

visualization_msgs::MarkerArray ToBodyMarkers(const Model& model) {
  visualization_msgs::MarkerArray msg;
  const double scale = model.length_scale();
  for (size_t k = 0; k < model.bodies().size(); ++k) {
    const BodyInfo& body = model.bodies()[k];
    // the node sits at the centre of mass with the link frame's axes: a point p_N of the node frame is at
    // p_N - p_NBo_N in the link frame
    const Vec3 p_BoBcm_B = -body.p_NBo_N;
    visualization_msgs::Marker sphere = BodyMarker(body, static_cast<int>(2 * k), visualization_msgs::Marker::SPHERE);
    sphere.pose.position = ToPoint(p_BoBcm_B);
    sphere.scale.x = sphere.scale.y = sphere.scale.z = kComSphereDiameter * scale;
    msg.markers.push_back(sphere);

    visualization_msgs::Marker sticks =
        BodyMarker(body, static_cast<int>(2 * k + 1), visualization_msgs::Marker::LINE_LIST);
    sticks.scale.x = kStickWidth * scale;
    for (const Joint* joint : model.joints()) {
      for (const Joint::Attachment* side : {&joint->parent(), &joint->child()}) {
        if (side->node != body.node) continue;
        sticks.points.push_back(ToPoint(p_BoBcm_B));
        sticks.points.push_back(ToPoint(side->p_NJ - body.p_NBo_N));
      }
    }
    if (!sticks.points.empty()) msg.markers.push_back(sticks);
  }
  return msg;
}

}  // namespace ros
}  // namespace flexmbd
