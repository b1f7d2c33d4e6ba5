#pragma once
/// @file
/// Typed, validated reading of YAML fields (docs/config.md). Every reader throws ConfigError with a one-line
/// message "<file>: <field path>: <offending value> <problem>; expected <form>". A value that is present but
/// of the wrong type or out of range is always an error, never a silent default.

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace io {

/// A YAML node and where it sits: the file name and the dotted field path ("joints.B1.spring.k").
class Field {
 public:
  /// The document root of `file`.
  Field(const YAML::Node& node, std::string file);

  /// The value under `key` of a map; absent if the map lacks it or this field is not a map.
  Field Child(const std::string& key) const;

  /// Entry `index` of a list. @pre the field is a list with more than `index` entries.
  Field Entry(size_t index) const;

  /// True if the key was written (even with an empty value).
  bool present() const { return present_; }
  /// True if the key was written with an empty value (`key:` or `key: ~`).
  bool empty() const { return present_ && node_.IsNull(); }
  const YAML::Node& node() const { return node_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

  /// The value as written, in flow style and abbreviated, for messages ("-3", "[1, 2]").
  std::string Text() const;

  /// The value with its type, for type errors ("'soft'", "a list [1, 2]", "an empty value").
  std::string Describe() const;

  /// "<file>: <path>: <what>" on one line: the text of an error (Fail) or of a warning (ModelSpec::warnings).
  std::string Message(const std::string& what) const;

  /// Throws ConfigError(Message(what)).
  [[noreturn]] void Fail(const std::string& what) const;

 private:
  Field(YAML::Node node, std::string file, std::string path, bool present);
  YAML::Node node_;
  std::string file_;
  std::string path_;
  bool present_ = true;
};

/// The range a number must lie in (kUnitInterval [0, 1], kPositiveFraction (0, 1]).
enum class Bound { kAny, kNonNegative, kPositive, kUnitInterval, kPositiveFraction, kAtLeastOne };

/// What a number means, for its range check and its messages: {"a stiffness", kNonNegative, "N m/rad"}
/// reads "expected a stiffness >= 0 [N m/rad]".
struct Quantity {
  std::string name;
  Bound bound = Bound::kAny;
  std::string unit;  ///< SI unit; empty for a plain number
  std::string components = "[x, y, z]";  ///< a vector's entries, as docs/config.md names them (ReadVec3)
};

/// "a stiffness >= 0 [N m/rad]".
std::string Expected(const Quantity& quantity);

/// Checks that the field is a map (an empty value counts as an empty map) whose keys are unique and all in
/// `valid`; an unknown key fails with the closest valid key suggested, or with the list of valid keys.
void CheckKeys(const Field& field, const std::vector<std::string>& valid);

/// The keys of a map in document order (an empty value gives none); fails on duplicates or a non-map
/// with "expected <what>".
std::vector<std::string> MapKeys(const Field& field, const std::string& what);

/// The entries of a list (an empty value gives none); fails on a non-list with "expected <what>".
std::vector<Field> ListEntries(const Field& field, const std::string& what);

/// Fails with "missing key '<key>'; expected <why>" if `map` lacks `key`.
void RequireKey(const Field& map, const std::string& key, const std::string& why);

/// A finite number in the range of `quantity`, multiplied by `to_si` after the range check; a quoted scalar ("100")
/// is text, not a number.
double ReadNumber(const Field& field, const Quantity& quantity, double to_si = 1.0);

/// An integer in the range of `quantity`, not quoted.
int ReadInteger(const Field& field, const Quantity& quantity);

/// true or false (YAML 1.2: also True, TRUE, False, FALSE), not quoted; YAML 1.1's yes/no, on/off are refused.
bool ReadBool(const Field& field);

/// A scalar read as text (a file path, a name).
std::string ReadString(const Field& field, const std::string& what);

/// A list of exactly three numbers.
Vec3 ReadVec3(const Field& field, const Quantity& quantity);

/// A list of numbers, each in the range of `quantity`, each multiplied by `to_si`.
std::vector<double> ReadNumberList(const Field& field, const Quantity& quantity, double to_si = 1.0);

/// The index of the field's text among `names`; fails listing them (with a suggestion when one is close).
size_t ReadChoice(const Field& field, const std::string& what, const std::vector<std::string>& names);

/// One of several named values of an enum type.
template <typename E>
E ReadEnum(const Field& field, const std::string& what, const std::vector<std::pair<std::string, E>>& choices) {
  std::vector<std::string> names;
  for (const auto& choice : choices) names.push_back(choice.first);
  return choices[ReadChoice(field, what, names)].second;
}

/// Overwrites *value with map[key] if the key is present; leaves the default otherwise.
void OverlayNumber(const Field& map, const std::string& key, const Quantity& quantity, double* value);
void OverlayInteger(const Field& map, const std::string& key, const Quantity& quantity, int* value);
void OverlayBool(const Field& map, const std::string& key, bool* value);
void OverlayString(const Field& map, const std::string& key, const std::string& what, std::string* value);
void OverlayVec3(const Field& map, const std::string& key, const Quantity& quantity, Vec3* value);

/// OverlayInteger of a count that also fails above `most`: "<n> is above <most>; expected at most <most> <what>".
void OverlayCount(const Field& map, const std::string& key, const Quantity& quantity, int most,
                  const std::string& what, int* value);

/// What a value that may be written in degrees measures.
struct Measure {
  bool angular = false;     ///< degrees allowed under `<key>_deg`
  std::string description;  ///< for messages: "variable 0 (s) of prismatic joint 'slide'"
};

/// The field given for a value written either as `key` (SI) or `key_deg` (degrees, angular measures only),
/// with the factor to SI and the unit it is written in ("rad/s" or "deg/s").
struct UnitField {
  Field field;
  double to_si;
  std::string unit;
};

/// Finds `key` or `key_deg` in `map`; nullopt if neither is present. Fails if both are present, or if
/// `key_deg` is used for a measure that is not an angle. `si_unit` is the SI unit of `key` ("rad/s").
std::optional<UnitField> FindUnitField(const Field& map, const std::string& key, const std::string& si_unit,
                                       const Measure& measure);

/// Overwrites *value (SI) with `key` or `key_deg`, whichever is present; returns that field, nullopt if neither is.
std::optional<UnitField> OverlayMeasure(const Field& map, const std::string& key, Quantity quantity,
                                        const Measure& measure, double* value);

}  // namespace io
}  // namespace flexmbd
