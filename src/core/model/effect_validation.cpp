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

}  // namespace flexmbd
