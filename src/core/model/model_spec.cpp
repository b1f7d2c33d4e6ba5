#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

int NumJointVariables(JointType type) {
  switch (type) {
    case JointType::kRevolute:
    case JointType::kPrismatic:
    case JointType::kScrew:
      return 1;
    case JointType::kCylindrical:
    case JointType::kUniversal:
      return 2;
    case JointType::kPlanar:
      return 3;
    case JointType::kSpherical:
    case JointType::kFixed:
      return 0;
  }
  return 0;
}

const char* JointTypeName(JointType type) {
  switch (type) {
    case JointType::kRevolute: return "revolute";
    case JointType::kPrismatic: return "prismatic";
    case JointType::kCylindrical: return "cylindrical";
    case JointType::kScrew: return "screw";
    case JointType::kPlanar: return "planar";
    case JointType::kSpherical: return "spherical";
    case JointType::kUniversal: return "universal";
    case JointType::kFixed: return "fixed";
  }
  return "unknown";
}

}  // namespace flexmbd
