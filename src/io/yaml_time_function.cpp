#include <algorithm>
#include <utility>

#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {
namespace {
using Kind = TimeFunctionSpec::Kind;

// What a scalar key of a time function measures.
enum class KeyUnit { kValue, kRate, kAngle, kTime, kFrequency };

struct ScalarKey {
  const char* name;
  double TimeFunctionSpec::*member;
  KeyUnit unit;
  Bound bound;
  const char* quantity;
};

const ScalarKey kScalarKeys[] = {
    {"value", &TimeFunctionSpec::value, KeyUnit::kValue, Bound::kAny, "a value"},
    {"rate", &TimeFunctionSpec::value, KeyUnit::kRate, Bound::kAny, "a rate"},
    {"offset", &TimeFunctionSpec::offset, KeyUnit::kValue, Bound::kAny, "an offset"},
    {"amplitude", &TimeFunctionSpec::amplitude, KeyUnit::kValue, Bound::kAny, "an amplitude"},
    {"start", &TimeFunctionSpec::start, KeyUnit::kTime, Bound::kAny, "a start time"},
    {"duration", &TimeFunctionSpec::duration, KeyUnit::kTime, Bound::kPositive, "a duration"},
    {"frequency", &TimeFunctionSpec::frequency, KeyUnit::kFrequency, Bound::kPositive, "a frequency"},
    {"phase", &TimeFunctionSpec::phase, KeyUnit::kAngle, Bound::kAny, "a phase"},
};

struct Law {
  std::string name;
  Kind kind;
  std::vector<std::string> keys;  ///< the keys this law takes, besides `law` (SI forms)
};

const std::vector<Law>& Laws() {
  static const std::vector<Law> laws = {
      {"constant", Kind::kConstant, {"value"}},
      {"linear_ramp", Kind::kLinearRamp, {"value", "offset", "start", "duration"}},
      {"cosine_ramp", Kind::kCosineRamp, {"value", "offset", "start", "duration"}},
      {"rate_ramp", Kind::kRateRamp, {"rate", "offset", "start", "duration"}},
      {"sine", Kind::kSine, {"offset", "amplitude", "frequency", "phase", "start"}},
      {"table", Kind::kTable, {"times", "values"}},
  };
  return laws;
}

// Keys that may also be written in degrees: the values of the function (in the driven variable's unit), its
// rate (deg/s) and the phase.
bool HasDegreeForm(const std::string& key) {
  if (key == "values") return true;
  for (const ScalarKey& scalar : kScalarKeys) {
    if (key == scalar.name) return scalar.unit != KeyUnit::kTime && scalar.unit != KeyUnit::kFrequency;
  }
  return false;
}

// `law` and the keys of `laws`, each with its _deg form where it has one.
std::vector<std::string> KeysOf(const std::vector<Law>& laws) {
  std::vector<std::string> keys = {"law"};
  for (const Law& law : laws) {
    for (const std::string& key : law.keys) {
      for (const std::string& form :
           HasDegreeForm(key) ? std::vector<std::string>{key, key + "_deg"} : std::vector<std::string>{key}) {
        if (std::find(keys.begin(), keys.end(), form) == keys.end()) keys.push_back(form);
      }
    }
  }
  return keys;
}

const Law& ReadLaw(const Field& map) {
  std::vector<std::string> names;
  for (const Law& law : Laws()) names.push_back(law.name);
  RequireKey(map, "law", "one of " + JoinNames(names));
  return Laws()[ReadChoice(map.Child("law"), "law", names)];
}

// Rejects keys of other laws with the keys this law takes.
void CheckLawKeys(const Field& map, const Law& law) {
  const std::vector<std::string> valid = KeysOf({law});
  for (const std::string& key : MapKeys(map, "a time function")) {
    if (std::find(valid.begin(), valid.end(), key) == valid.end()) {
      map.Child(key).Fail("does not apply to law '" + law.name + "'; it takes: " + JoinNames(valid));
    }
  }
}

// The unit a scalar key is written in, and what it measures (which decides whether `<key>_deg` is allowed).
std::pair<std::string, Measure> UnitOf(const ScalarKey& key, const std::string& unit, const Measure& measure) {
  switch (key.unit) {
    case KeyUnit::kValue: return {unit, measure};
    case KeyUnit::kRate: return {unit + "/s", measure};
    case KeyUnit::kAngle: return {"rad", Measure{true, "a phase"}};
    case KeyUnit::kTime: return {"s", Measure{false, key.quantity}};
    case KeyUnit::kFrequency: return {"Hz", Measure{false, key.quantity}};
  }
  return {unit, measure};
}

void ReadScalarKey(const Field& map, const ScalarKey& key, const std::string& unit, const Measure& measure,
                   TimeFunctionSpec* f) {
  const auto [key_unit, key_measure] = UnitOf(key, unit, measure);
  OverlayMeasure(map, key.name, Quantity{key.quantity, key.bound, key_unit}, key_measure, &(f->*key.member));
}

void CheckIncreasing(const Field& times, const std::vector<double>& values) {
  for (size_t i = 1; i < values.size(); ++i) {
    if (!(values[i] > values[i - 1])) {
      times.Entry(i).Fail(times.Entry(i).Text() + " is not greater than the previous time " +
                          FormatNumber(values[i - 1]) + "; expected strictly increasing times [s]");
    }
  }
}

void ReadTable(const Field& map, const std::string& unit, const Measure& measure, TimeFunctionSpec* f) {
  RequireKey(map, "times", "a list of strictly increasing times [s]");
  const Field times = map.Child("times");
  f->times = ReadNumberList(times, Quantity{"a time", Bound::kAny, "s"});
  if (f->times.empty()) times.Fail(times.Text() + " is empty; expected at least one time [s]");
  CheckIncreasing(times, f->times);
  const std::optional<UnitField> values = FindUnitField(map, "values", unit, measure);
  if (!values) map.Fail("missing key 'values'; expected one value per time");
  f->values = ReadNumberList(values->field, Quantity{"a value", Bound::kAny, values->unit}, values->to_si);
  if (f->values.size() != f->times.size()) {
    values->field.Fail("has " + std::to_string(f->values.size()) + " entries but times has " +
                       std::to_string(f->times.size()) + "; expected one value per time");
  }
}

// A sine without its amplitude or its frequency is a constant, which a forgotten key would give without a word.
void RequireSineKeys(const Field& map, const std::string& unit, const Measure& measure) {
  const std::string constant = " (a sine without it is a constant: law: constant)";
  if (!FindUnitField(map, "amplitude", unit, measure)) {
    map.Fail("missing key 'amplitude'" + std::string(measure.angular ? " (or amplitude_deg)" : "") +
             "; expected the sine's amplitude" + (unit.empty() ? "" : " [" + unit + "]") + constant);
  }
  RequireKey(map, "frequency", "a frequency > 0 [Hz]" + constant);
}
}  // namespace

TimeFunctionSpec ReadTimeFunction(const Field& map, const std::string& unit, const Measure& measure) {
  CheckKeys(map, KeysOf(Laws()));
  const Law& law = ReadLaw(map);
  CheckLawKeys(map, law);
  TimeFunctionSpec f;
  f.kind = law.kind;
  if (law.kind == Kind::kTable) {
    ReadTable(map, unit, measure, &f);
    return f;
  }
  if (law.kind == Kind::kSine) RequireSineKeys(map, unit, measure);
  for (const ScalarKey& key : kScalarKeys) {
    if (std::find(law.keys.begin(), law.keys.end(), key.name) != law.keys.end())
      ReadScalarKey(map, key, unit, measure, &f);
  }
  return f;
}

}  // namespace io
}  // namespace flexmbd
