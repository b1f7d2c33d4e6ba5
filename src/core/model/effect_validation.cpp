#include "flexmbd/model/effect_validation.hpp"

#include <sstream>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace {
[[noreturn]] void Fail(const std::string& where, const std::string& field, double value, const std::string& expected) {
  std::ostringstream msg;
  msg << where << field << ": " << value << " is out of range; expected " << expected;
  throw ConfigError(msg.str());
}
}  // namespace

void ValidateStop(const std::string& where, const StopSpec& stop) {
  const std::string at = where + "stop '" + stop.name + "': ";
  if (!(stop.radius > 0)) Fail(at, "radius", stop.radius, "a contact radius > 0 [m]");
  const StopSpec::Retraction& r = stop.retraction;
  if (!r.joint.empty() && !(r.engage_below >= 0 && r.engage_below < r.retract_above)) {
    Fail(at, "retract.engage_below", r.engage_below, "0 <= engage_below < retract_above");
  }
  if (stop.kind == StopSpec::Kind::kRigid) return;
  if (!(stop.stiffness > 0)) Fail(at, "stiffness", stop.stiffness, "a contact stiffness > 0 [N/m^n]");
  if (stop.law == StopSpec::Law::kHertz && !(stop.exponent >= 1)) Fail(at, "exponent", stop.exponent, "n >= 1");
  if (!(stop.restitution > 0 && stop.restitution <= 1)) {
    Fail(at, "restitution", stop.restitution, "a coefficient of restitution in (0, 1]");
  }
  if (stop.steps_per_contact < 1) Fail(at, "steps_per_contact", stop.steps_per_contact, "an integer >= 1");
}

void ValidateFriction(const std::string& where, const FrictionSpec& f, JointType type) {
  const std::string at = where + "friction: ";
  if (type != JointType::kRevolute && type != JointType::kPrismatic) {
    // A constant bound comes only from the URDF's <dynamics friction>: say so, the YAML may have none.
    const std::string source = f.law == FrictionSpec::Law::kConstantTorque ? "the URDF's <dynamics friction> on " : "";
    throw ConfigError(at + source + "a " + JointTypeName(type) +
                      " joint; expected friction on a revolute or prismatic joint");
  }
  if (f.law == FrictionSpec::Law::kConstantTorque) {
    if (!(f.torque >= 0)) Fail(at, "torque", f.torque, "a friction torque >= 0 [N m or N]");
    return;
  }
  if (!(f.mu_k >= 0)) Fail(at, "mu_k", f.mu_k, "a kinetic coefficient >= 0");
  if (!(f.mu_s >= f.mu_k)) Fail(at, "mu_s", f.mu_s, "a static coefficient >= mu_k (" + std::to_string(f.mu_k) + ")");
  if (!(f.radius > 0)) Fail(at, "radius", f.radius, "a race radius > 0 [m]");
  if (!(f.preload >= 0)) Fail(at, "preload", f.preload, "a preload >= 0 [N]");
  if (!(f.v0 >= 0)) {
    Fail(at, "v0", f.v0, "a sticking speed >= 0 [m/s] (0: 100 error_tol, at most 1%, of the largest slip speed)");
  }
  if (f.law == FrictionSpec::Law::kRegularised && !(f.v0 > 0)) {
    Fail(at, "v0", f.v0, "a regularisation speed > 0 [m/s] for the regularised law");
  }
}

}  // namespace flexmbd
