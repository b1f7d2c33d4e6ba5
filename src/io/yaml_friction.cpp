#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {
namespace {
const std::vector<std::string> kFrictionKeys = {"law", "mu_s", "mu_k", "radius", "preload", "v0"};
}  // namespace

FrictionSpec ReadFriction(const Field& field, const VariableUnits& units) {
  CheckKeys(field, kFrictionKeys);
  FrictionSpec friction;
  if (field.Child("law").present()) {
    friction.law = ReadEnum<FrictionSpec::Law>(
        field.Child("law"), "friction law",
        {{"coulomb_stick", FrictionSpec::Law::kCoulombStick}, {"regularised", FrictionSpec::Law::kRegularised}});
  }
  const Quantity coefficient{"a friction coefficient", Bound::kNonNegative, ""};
  RequireKey(field, "mu_k", Expected(coefficient));
  friction.mu_k = ReadNumber(field.Child("mu_k"), coefficient);
  friction.mu_s = friction.mu_k;
  if (friction.law == FrictionSpec::Law::kRegularised && field.Child("mu_s").present()) {
    field.Child("mu_s").Fail("the regularised law mu_k rho N (1 - exp(-|v|/v0)) never sticks and has no static "
                             "coefficient; expected no mu_s with law: regularised (or law: coulomb_stick, which "
                             "sticks within mu_s rho N)");
  }
  OverlayNumber(field, "mu_s", coefficient, &friction.mu_s);
  if (friction.mu_s < friction.mu_k) {
    field.Child("mu_s").Fail(FormatNumber(friction.mu_s) + " is below mu_k " + FormatNumber(friction.mu_k) +
                             "; expected mu_s >= mu_k");
  }
  if (field.Child("radius").present() && !units.measure.angular) {
    field.Child("radius").Fail("applies only to rotations; friction on " + units.measure.description +
                               " acts along its travel");
  }
  OverlayNumber(field, "radius", Quantity{"a race radius", Bound::kPositive, "m"}, &friction.radius);
  OverlayNumber(field, "preload", Quantity{"a preload", Bound::kNonNegative, "N"}, &friction.preload);
  const bool regularised = friction.law == FrictionSpec::Law::kRegularised;
  const Quantity speed{regularised ? "a regularisation speed" : "a sticking speed",
                       regularised ? Bound::kPositive : Bound::kNonNegative, "m/s"};
  if (regularised) RequireKey(field, "v0", Expected(speed) + " for the regularised law");
  OverlayNumber(field, "v0", speed, &friction.v0);
  return friction;
}

}  // namespace io
}  // namespace flexmbd
