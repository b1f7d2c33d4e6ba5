#include "flexmbd/io/yaml_fields.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/message_text.hpp"

namespace flexmbd {
namespace io {
namespace {
// Longest value text quoted in a message.
constexpr size_t kMaxTextLength = 60;

const double kDegreesToRadians = M_PI / 180.0;

std::string JoinPath(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

std::string OneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  if (text.size() > kMaxTextLength) text = text.substr(0, kMaxTextLength - 3) + "...";
  return text;
}

std::string BoundText(Bound bound) {
  switch (bound) {
    case Bound::kAny: return "";
    case Bound::kNonNegative: return " >= 0";
    case Bound::kPositive: return " > 0";
    case Bound::kUnitInterval: return " in [0, 1]";
    case Bound::kPositiveFraction: return " in (0, 1]";
    case Bound::kAtLeastOne: return " >= 1";
  }
  return "";
}

// What is wrong with `value` for `bound`; empty if it lies in range.
std::string BoundViolation(double value, Bound bound) {
  switch (bound) {
    case Bound::kAny: return "";
    case Bound::kNonNegative: return value < 0.0 ? "is negative" : "";
    case Bound::kPositive: return value < 0.0 ? "is negative" : value == 0.0 ? "is zero" : "";
    case Bound::kUnitInterval: return value < 0.0 || value > 1.0 ? "is outside [0, 1]" : "";
    case Bound::kPositiveFraction: return value <= 0.0 || value > 1.0 ? "is outside (0, 1]" : "";
    case Bound::kAtLeastOne: return value < 1.0 ? "is less than 1" : "";
  }
  return "";
}

void CheckBound(const Field& field, double value, const Quantity& quantity) {
  const std::string violation = BoundViolation(value, quantity.bound);
  if (!violation.empty()) field.Fail(field.Text() + " " + violation + "; expected " + Expected(quantity));
}

// "rad/s" -> "deg/s": the unit of the same value written in degrees.
std::string DegreeUnit(std::string unit) {
  const size_t at = unit.find("rad");
  if (at != std::string::npos) unit.replace(at, 3, "deg");
  return unit;
}

// True for a scalar that is a decimal number too large for a double (1e400; 1e-400 reads as 0), which yaml-cpp
// refuses as it refuses text.
bool OutOfDoubleRange(const Field& field) {
  if (!field.node().IsScalar()) return false;
  const std::string& text = field.node().Scalar();
  char* end = nullptr;
  errno = 0;
  std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && errno == ERANGE;
}

// A quoted (or block) scalar is text, whatever it reads ("100", 'true'): the schema's numbers and booleans are
// plain scalars, as YAML 1.2 resolves them. yaml-cpp tags a parsed quoted scalar "!" and a plain one "?"; the
// node the ROS node builds from its parameters has none (rosparam has typed them already).
void RejectQuoted(const Field& field, const std::string& expected) {
  if (field.node().IsScalar() && field.node().Tag() == "!") {
    field.Fail("\"" + field.Text() + "\" is quoted, which makes it a text; expected " + expected +
               ", written without quotes");
  }
}

// The YAML 1.2 core schema's booleans; yes, no, on, off and their kin are YAML 1.1's, and read as text there.
std::optional<bool> Yaml12Bool(const std::string& text) {
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  return std::nullopt;
}

}  // namespace

Field::Field(const YAML::Node& node, std::string file) : Field(node, std::move(file), "", true) {}

Field::Field(YAML::Node node, std::string file, std::string path, bool present)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)), present_(present) {}

Field Field::Child(const std::string& key) const {
  if (present_ && node_.IsMap()) {
    for (auto it = node_.begin(); it != node_.end(); ++it) {
      if (it->first.IsScalar() && it->first.Scalar() == key)
        return Field(it->second, file_, JoinPath(path_, key), true);
    }
  }
  return Field(YAML::Node(), file_, JoinPath(path_, key), false);
}

Field Field::Entry(size_t index) const {
  return Field(node_[index], file_, path_ + "[" + std::to_string(index) + "]", true);
}

std::string Field::Text() const {
  if (node_.IsScalar()) return OneLine(node_.Scalar());
  if (node_.IsNull()) return "~";
  YAML::Emitter emitter;
  emitter << YAML::Flow << node_;
  return OneLine(emitter.c_str());
}

std::string Field::Describe() const {
  if (node_.IsNull()) return "an empty value";
  if (node_.IsScalar()) return "'" + Text() + "'";
  return (node_.IsSequence() ? "a list " : "a map ") + Text();
}

std::string Field::Message(const std::string& what) const {
  // keys and values in the path and the text are the user's: a newline in one must not break the line
  return QuoteForMessage(file_ + ": " + (path_.empty() ? "" : path_ + ": ") + what);
}

void Field::Fail(const std::string& what) const { throw ConfigError(Message(what)); }

std::string Expected(const Quantity& quantity) {
  return quantity.name + BoundText(quantity.bound) + (quantity.unit.empty() ? "" : " [" + quantity.unit + "]");
}

std::vector<std::string> MapKeys(const Field& field, const std::string& what) {
  if (!field.present() || field.empty()) return {};
  if (!field.node().IsMap()) field.Fail(field.Describe() + " is not a map; expected " + what);
  std::vector<std::string> keys;
  for (auto it = field.node().begin(); it != field.node().end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : "";
    if (key.empty()) field.Fail("a key is empty or not a name; expected " + what);
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) field.Child(key).Fail("duplicate key; give it once");
    keys.push_back(key);
  }
  return keys;
}

void CheckKeys(const Field& field, const std::vector<std::string>& valid) {
  for (const std::string& key : MapKeys(field, "a map with keys " + JoinNames(valid))) {
    if (std::find(valid.begin(), valid.end(), key) == valid.end()) {
      field.Child(key).Fail("unknown key; " + SuggestName(key, valid, "valid keys"));
    }
  }
}

std::vector<Field> ListEntries(const Field& field, const std::string& what) {
  if (!field.present() || field.empty()) return {};
  if (!field.node().IsSequence()) field.Fail(field.Describe() + " is not a list; expected " + what);
  std::vector<Field> entries;
  for (size_t i = 0; i < field.node().size(); ++i) entries.push_back(field.Entry(i));
  return entries;
}

void RequireKey(const Field& map, const std::string& key, const std::string& why) {
  if (!map.Child(key).present()) map.Fail("missing key '" + key + "'; expected " + why);
}

double ReadNumber(const Field& field, const Quantity& quantity, double to_si) {
  RejectQuoted(field, Expected(quantity));
  double value = 0.0;
  bool ok = field.node().IsScalar();
  if (ok) {
    try {
      value = field.node().as<double>();
    } catch (const YAML::Exception&) {
      ok = false;
    }
  }
  if (!ok && OutOfDoubleRange(field)) {
    field.Fail(field.Text() + " is a number beyond the range of a double (largest magnitude 1.8e308); expected " +
               Expected(quantity));
  }
  if (!ok) field.Fail(field.Describe() + " is not a number; expected " + Expected(quantity));
  if (!std::isfinite(value)) field.Fail(field.Text() + " is not finite; expected " + Expected(quantity));
  CheckBound(field, value, quantity);
  return value * to_si;
}

int ReadInteger(const Field& field, const Quantity& quantity) {
  RejectQuoted(field, Expected(quantity));
  int value = 0;
  bool ok = field.node().IsScalar();
  if (ok) {
    try {
      value = field.node().as<int>();
    } catch (const YAML::Exception&) {
      ok = false;
    }
  }
  if (!ok) field.Fail(field.Describe() + " is not an integer; expected " + Expected(quantity));
  CheckBound(field, value, quantity);
  return value;
}

bool ReadBool(const Field& field) {
  RejectQuoted(field, "true or false");
  if (field.node().IsScalar()) {
    if (const std::optional<bool> value = Yaml12Bool(field.node().Scalar())) return *value;
  }
  field.Fail(field.Describe() + " is not a boolean; expected true or false");
}

std::string ReadString(const Field& field, const std::string& what) {
  if (!field.node().IsScalar()) field.Fail(field.Describe() + " is not a text; expected " + what);
  return field.node().Scalar();
}

Vec3 ReadVec3(const Field& field, const Quantity& quantity) {
  const std::string expected = "expected " + quantity.components + ", " + Expected(quantity);
  if (!field.node().IsSequence()) field.Fail(field.Describe() + " is not a list; " + expected);
  if (field.node().size() != 3) {
    field.Fail(field.Text() + " has " + std::to_string(field.node().size()) + " entries; " + expected);
  }
  Vec3 value;
  for (size_t i = 0; i < 3; ++i) value[i] = ReadNumber(field.Entry(i), quantity);
  return value;
}

std::vector<double> ReadNumberList(const Field& field, const Quantity& quantity, double to_si) {
  if (!field.node().IsSequence()) {
    field.Fail(field.Describe() + " is not a list; expected a list of " + Expected(quantity));
  }
  std::vector<double> values;
  for (size_t i = 0; i < field.node().size(); ++i) values.push_back(ReadNumber(field.Entry(i), quantity, to_si));
  return values;
}

size_t ReadChoice(const Field& field, const std::string& what, const std::vector<std::string>& names) {
  if (field.node().IsScalar()) {
    const auto found = std::find(names.begin(), names.end(), field.node().Scalar());
    if (found != names.end()) return static_cast<size_t>(found - names.begin());
  }
  const std::string closest = field.node().IsScalar() ? ClosestName(field.node().Scalar(), names) : "";
  field.Fail(field.Describe() + " is not a valid " + what + "; expected one of " + JoinNames(names) +
             (closest.empty() ? "" : "; did you mean '" + closest + "'?"));
}

void OverlayNumber(const Field& map, const std::string& key, const Quantity& quantity, double* value) {
  const Field field = map.Child(key);
  if (field.present()) *value = ReadNumber(field, quantity);
}

void OverlayInteger(const Field& map, const std::string& key, const Quantity& quantity, int* value) {
  const Field field = map.Child(key);
  if (field.present()) *value = ReadInteger(field, quantity);
}

void OverlayCount(const Field& map, const std::string& key, const Quantity& quantity, int most,
                  const std::string& what, int* value) {
  OverlayInteger(map, key, quantity, value);
  if (*value > most) {
    map.Child(key).Fail(std::to_string(*value) + " is above " + std::to_string(most) + "; expected at most " +
                        std::to_string(most) + " " + what);
  }
}

void OverlayBool(const Field& map, const std::string& key, bool* value) {
  const Field field = map.Child(key);
  if (field.present()) *value = ReadBool(field);
}

void OverlayString(const Field& map, const std::string& key, const std::string& what, std::string* value) {
  const Field field = map.Child(key);
  if (field.present()) *value = ReadString(field, what);
}

void OverlayVec3(const Field& map, const std::string& key, const Quantity& quantity, Vec3* value) {
  const Field field = map.Child(key);
  if (field.present()) *value = ReadVec3(field, quantity);
}

std::optional<UnitField> FindUnitField(const Field& map, const std::string& key, const std::string& si_unit,
                                       const Measure& measure) {
  const Field si = map.Child(key);
  const Field degrees = map.Child(key + "_deg");
  if (si.present() && degrees.present()) {
    degrees.Fail("both '" + key + "' and '" + key + "_deg' are given; expected one of them");
  }
  if (degrees.present()) {
    if (!measure.angular) {
      degrees.Fail("degrees apply only to angles; " + measure.description + " is not an angle: use '" + key + "'" +
                   (si_unit.empty() ? "" : " [" + si_unit + "]"));
    }
    return UnitField{degrees, kDegreesToRadians, DegreeUnit(si_unit)};
  }
  if (si.present()) return UnitField{si, 1.0, si_unit};
  return std::nullopt;
}

std::optional<UnitField> OverlayMeasure(const Field& map, const std::string& key, Quantity quantity,
                                        const Measure& measure, double* value) {
  const std::optional<UnitField> found = FindUnitField(map, key, quantity.unit, measure);
  if (!found) return std::nullopt;
  quantity.unit = found->unit;
  *value = ReadNumber(found->field, quantity, found->to_si);
  return found;
}

}  // namespace io
}  // namespace flexmbd
