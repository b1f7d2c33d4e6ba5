#include "flexmbd/ros/message_conversions.hpp"

#include <Eigen/Geometry>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace ros {
namespace {

// Marker sizes relative to the model's length scale (its largest node distance from the origin).
constexpr double kComSphereDiameter = 0.06;
constexpr double kStickWidth = 0.015;
constexpr double kBeamNodeDiameter = 0.03;

void SetVector3(const Vec3& v, geometry_msgs::Vector3* out) {
  out->x = v.x();
  out->y = v.y();
  out->z = v.z();
}

geometry_msgs::Point ToPoint(const Vec3& v) {
  geometry_msgs::Point out;
  out.x = v.x();
  out.y = v.y();
  out.z = v.z();
  return out;
}

struct Pose {
  Mat3 R;
  Vec3 p;  ///< [m]
};

// The world pose of a frame placed on a node of `state` (or on the ground).
Pose WorldPose(const FramePlacement& at, const State& state) {
  if (at.node < 0) return Pose{at.R_NF, at.p_NF_N};
  const NodeState& node = state.nodes[at.node];
  return Pose{node.R * at.R_NF, node.x + node.R * at.p_NF_N};
}

void SetTransform(const Mat3& R, const Vec3& p, geometry_msgs::Transform* out) {
  SetVector3(p, &out->translation);
  const Eigen::Quaterniond q(R);
  out->rotation.x = q.x();
  out->rotation.y = q.y();
  out->rotation.z = q.z();
  out->rotation.w = q.w();
}

void SetVector(const Eigen::VectorXd& v, std::vector<double>* out) { out->assign(v.data(), v.data() + v.size()); }

visualization_msgs::Marker FrameMarker(const std::string& frame, const std::string& ns, int id, int type) {
  visualization_msgs::Marker marker;
  marker.header.frame_id = frame;
  marker.ns = ns;
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

// One message entry per record of the model: Set(infos[k], records[k], &entries[k]). The sample's records
// follow the model's list (OutputSample): the same order and size.
template <typename Info, typename Record, typename Entry, typename Set>
void FillNamedRecords(const std::vector<Info>& infos, const std::vector<Record>& records, std::vector<Entry>* entries,
                      Set set) {
  FLEXMBD_DEMAND(records.size() == infos.size());
  entries->resize(infos.size());
  for (size_t k = 0; k < infos.size(); ++k) set(infos[k], records[k], &(*entries)[k]);
}

// The values of an aero section or strip station sample into its message (the fields share their names).
template <typename AeroLoads>
void SetAeroValues(const AeroSectionSample& value, AeroLoads* msg) {
  msg->lift = value.lift;
  msg->moment = value.moment;
  msg->hinge_moment = value.hinge_moment;
  SetVector(value.inflow, &msg->inflow);
}
}  // namespace

::ros::Time ToStamp(double t) { return ::ros::Time(t); }

void FillJointState(const Model& model, const OutputSample& sample, sensor_msgs::JointState* msg) {
  msg->name = model.variable_names();
  SetVector(sample.position, &msg->position);
  SetVector(sample.velocity, &msg->velocity);
  SetVector(sample.effort, &msg->effort);
}

void FillEnergy(const OutputSample& sample, Energy* msg) {
  msg->kinetic = sample.kinetic;
  msg->potential = sample.potential;
  msg->external_work = sample.external_work;
  msg->dissipated = sample.dissipated;
  msg->numerical_dissipation = sample.numerical_dissipation;
}

void FillJointReactions(const Model& model, const OutputSample& sample, JointReactionArray* msg) {
  const size_t n = model.joints().size();
  FLEXMBD_DEMAND(sample.reaction_force_W.size() == n && sample.reaction_moment.size() == n);
  msg->joints.resize(n);
  for (size_t k = 0; k < n; ++k) {
    JointReaction& reaction = msg->joints[k];
    reaction.joint = model.joints()[k]->name();
    SetVector3(sample.reaction_force_W[k], &reaction.force);
    SetVector3(sample.reaction_moment[k], &reaction.moment);
  }
}

void FillSolverStep(const OutputSample& sample, SolverStep* msg) {
  msg->dt = sample.dt;
  msg->iterations = sample.iterations;
}

void FillJointContacts(const std::vector<StopInfo>& stops, const OutputSample& sample, JointContactArray* msg) {
  FillNamedRecords(stops, sample.stops, &msg->contacts,
                   [](const StopInfo& info, const StopSample& value, JointContact* contact) {
                     contact->joint = info.joint;
                     contact->stop = info.stop;
                     contact->in_contact = value.in_contact;
                     contact->force = value.force;
                     contact->torque = value.torque;
                     contact->approach = value.approach;
                   });
}

void FillJointFriction(const std::vector<FrictionInfo>& frictions, const OutputSample& sample,
                       JointFrictionArray* msg) {
  FillNamedRecords(frictions, sample.friction, &msg->joints,
                   [](const FrictionInfo& info, const FrictionSample& value, JointFriction* friction) {
                     friction->joint = info.joint;
                     friction->sticking = value.sticking;
                     friction->torque = value.torque;
                     friction->normal_force = value.normal_force;
                     friction->slip_velocity = value.slip_velocity;
                     friction->work = value.work;
                   });
}

void FillBeamLoads(const std::vector<BeamStationInfo>& stations, const OutputSample& sample, BeamLoadsArray* msg) {
  FillNamedRecords(stations, sample.beam_stations, &msg->stations,
                   [](const BeamStationInfo& info, const BeamStationSample& value, BeamStationLoads* station) {
                     station->beam = info.beam;
                     station->station = info.index;
                     station->s = info.s;
                     station->N = value.load[0];
                     station->V2 = value.load[1];
                     station->V3 = value.load[2];
                     station->T = value.load[3];
                     station->M2 = value.load[4];
                     station->M3 = value.load[5];
                     station->e1 = value.strain[0];
                     station->g2 = value.strain[1];
                     station->g3 = value.strain[2];
                     station->k1 = value.strain[3];
                     station->k2 = value.strain[4];
                     station->k3 = value.strain[5];
                     SetVector3(value.displacement, &station->displacement);
                     SetVector3(value.rotation, &station->rotation);
                   });
}

void FillAeroLoads(const Model& model, const OutputSample& sample, AeroLoadsArray* msg) {
  FillNamedRecords(model.aero_sections(), sample.aero_sections, &msg->sections,
                   [](const TypicalSectionAero* info, const AeroSectionSample& value, AeroSectionLoads* section) {
                     section->section = info->name();
                     SetAeroValues(value, section);
                   });
  FillNamedRecords(model.strip_stations(), sample.strip_stations, &msg->strip_stations,
                   [](const StripStationInfo& info, const AeroSectionSample& value, AeroStripStationLoads* station) {
                     station->strip = info.strip;
                     station->station = info.index;
                     station->s = info.s;
                     SetAeroValues(value, station);
                   });
  FillNamedRecords(model.aero_rotors(), sample.aero_rotors, &msg->rotors,
                   [](const RotorInflow* info, const AeroRotorSample& value, AeroRotorInflow* rotor) {
                     rotor->rotor = info->name();
                     rotor->inflow = value.inflow;
                     rotor->thrust = value.thrust;
                   });
}

void FillTransforms(const std::vector<TransformFrame>& frames, const State& state, tf2_msgs::TFMessage* msg) {
  const ::ros::Time stamp = ToStamp(state.t);
  msg->transforms.resize(frames.size());
  for (size_t k = 0; k < frames.size(); ++k) {
    const Pose X_WF = WorldPose(frames[k].placement, state);
    const Pose X_WP = WorldPose(frames[k].parent_placement, state);
    geometry_msgs::TransformStamped& transform = msg->transforms[k];
    transform.header.stamp = stamp;
    transform.header.frame_id = frames[k].parent;
    transform.child_frame_id = frames[k].name;
    SetTransform(X_WP.R.transpose() * X_WF.R, X_WP.R.transpose() * (X_WF.p - X_WP.p), &transform.transform);
  }
}

tf2_msgs::TFMessage ToStaticTransforms(const std::vector<StaticFrame>& frames) {
  tf2_msgs::TFMessage msg;
  msg.transforms.resize(frames.size());
  for (size_t k = 0; k < frames.size(); ++k) {
    geometry_msgs::TransformStamped& transform = msg.transforms[k];
    transform.header.frame_id = frames[k].parent;
    transform.child_frame_id = frames[k].name;
    SetTransform(frames[k].R_PF, frames[k].p_PF, &transform.transform);
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
    visualization_msgs::Marker sphere =
        FrameMarker(body.name, "bodies", static_cast<int>(2 * k), visualization_msgs::Marker::SPHERE);
    sphere.pose.position = ToPoint(p_BoBcm_B);
    sphere.scale.x = sphere.scale.y = sphere.scale.z = kComSphereDiameter * scale;
    msg.markers.push_back(sphere);

    visualization_msgs::Marker sticks =
        FrameMarker(body.name, "bodies", static_cast<int>(2 * k + 1), visualization_msgs::Marker::LINE_LIST);
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
  int beam_marker = 0;
  for (const BeamInfo& beam : model.beams()) {
    for (size_t k = 0; k < beam.nodes.size(); ++k) {
      visualization_msgs::Marker node = FrameMarker(BeamNodeFrameName(beam.name, k), "beam_nodes", beam_marker++,
                                                    visualization_msgs::Marker::SPHERE);
      node.scale.x = node.scale.y = node.scale.z = kBeamNodeDiameter * scale;
      msg.markers.push_back(node);
    }
  }
  return msg;
}

}  // namespace ros
}  // namespace flexmbd
