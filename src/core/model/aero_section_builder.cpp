#include "aero_section_builder.hpp"

#include <cmath>
#include <sstream>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace {
// An axis counts as along a world axis when its cosine with it is within this of +-1 (joint frames from URDF
// rpy in degrees carry ~1e-12 round-off).
constexpr double kAlignment = 1.0e-9;

const Joint* FindJoint(const Model& model, const std::string& field, const std::string& name) {
  for (const Joint* joint : model.joints()) {
    if (joint->name() == name) return joint;
  }
  throw ConfigError(field + ": no joint '" + name + "'; expected the name of a joint of the URDF");
}

// The type of a one-variable joint from its kinematics: a rotation factor (revolute) or a translation (prismatic).
bool IsRevolute(const JointKinematics& k) {
  return k.num_variables == 1 && k.rotations.size() == 1 && k.translation_rates_Jp[0].isZero();
}
bool IsPrismatic(const JointKinematics& k) { return k.num_variables == 1 && k.rotations.empty(); }

// The joint's motion axis in the world at the initial state, from its parent frame Jp.
Vec3 AxisInWorld(const Model& model, const Joint& joint) {
  const Joint::Attachment& parent = joint.parent();
  const Mat3 R_WN = parent.node < 0 ? Mat3::Identity() : Mat3(model.initial_state().nodes[parent.node].R);
  const JointKinematics& k = joint.kinematics();
  const Vec3 axis_Jp = IsRevolute(k) ? k.rotations[0].axis_J : k.translation_rates_Jp[0].normalized();
  return R_WN * parent.R_NJ * axis_Jp;
}
}  // namespace

std::unique_ptr<TypicalSectionAero> MakeAeroSection(const Model& model, const std::string& prefix,
                                                    const AeroSectionSpec& section, int first_state) {
  const std::string field = prefix + "aero.sections." + section.name;
  const char* roles[3] = {"plunge", "pitch", "flap"};
  const std::string* names[3] = {&section.plunge, &section.pitch, &section.flap};
  // Plunge h is positive down (-z), pitch and flap positive nose up and trailing edge down (+y, the free stream
  // along +x).
  const Vec3 directions[3] = {-Vec3::UnitZ(), Vec3::UnitY(), Vec3::UnitY()};
  const bool revolute[3] = {false, true, true};
  const Joint* joints[3];
  int node_unknowns[3];
  TypicalSectionAero::Coordinate coordinates[3];
  for (int k = 0; k < 3; ++k) {
    const std::string role_field = field + "." + roles[k];
    joints[k] = FindJoint(model, role_field, *names[k]);
    const JointKinematics& kinematics = joints[k]->kinematics();
    if (revolute[k] ? !IsRevolute(kinematics) : !IsPrismatic(kinematics)) {
      throw ConfigError(role_field + ": joint '" + *names[k] + "' is not a " +
                        (revolute[k] ? "revolute" : "prismatic") + " joint; expected a " +
                        (revolute[k] ? "revolute" : "prismatic") + " joint");
    }
    const double alignment = AxisInWorld(model, *joints[k]).dot(directions[k]);
    if (std::abs(std::abs(alignment) - 1.0) > kAlignment) {
      std::ostringstream msg;
      msg << role_field << ": joint '" << *names[k] << "' moves along/about an axis at cosine " << alignment + 0.0
          << " to the world " << (k == 0 ? "z" : "y") << " axis; expected the " << (k == 0 ? "z" : "y")
          << " axis (free stream along +x, lift along +z)";
      throw ConfigError(msg.str());
    }
    coordinates[k].variable = joints[k]->first_variable();
    coordinates[k].variable_unknown = model.variable_unknown(joints[k]->first_variable());
    coordinates[k].sign = alignment > 0 ? 1.0 : -1.0;
    node_unknowns[k] = joints[k]->child().first_unknown;
  }
  // Rates in the bodies' node frames: h' = -z . v_P, alpha' = y . w_A (the plunge body does not turn),
  // delta' = y . (w_F - w_A), w in W = R w_node (theory (A6)).
  const State& initial = model.initial_state();
  const Mat3& R_A = initial.nodes[joints[1]->child().node].R;
  const Mat3& R_F = initial.nodes[joints[2]->child().node].R;
  coordinates[0].rate.segment<3>(0) = -Vec3::UnitZ();
  coordinates[1].rate.segment<3>(3) = R_A.transpose() * Vec3::UnitY();
  coordinates[2].rate.segment<3>(6) = R_F.transpose() * Vec3::UnitY();
  coordinates[2].rate.segment<3>(3) = -R_A.transpose() * Vec3::UnitY();
  return std::make_unique<TypicalSectionAero>(section, node_unknowns, coordinates,
                                              model.element_state_unknown(first_state));
}

}  // namespace flexmbd
