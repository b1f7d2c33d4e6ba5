#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {
namespace {
// Most elements in one beam: 1e9 asked for more nodes than a std::vector holds (std::length_error, a fuzz
// finding); 1e6 cubic elements are 1.8e7 unknowns, far past what a run can factorise.
constexpr int kMaxBeamElements = 1000000;

const std::vector<std::string> kBeamKeys = {"length", "elements", "order", "damping", "section"};
const std::vector<std::string> kBeamSectionKeys = {"EA",        "GA2", "GA3", "GJ",   "EI2",    "EI3",
                                               "stiffness", "m",   "m_ii", "offsets"};
const std::vector<std::string> kOffsetKeys = {"cg", "shear_center"};
const char* kDiagonalKeys[6] = {"EA", "GA2", "GA3", "GJ", "EI2", "EI3"};
const char* kDiagonalUnits[6] = {"N", "N", "N", "N m^2", "N m^2", "N m^2"};

// Either the six diagonal stiffnesses or the full 6x6 `stiffness` (row by row, 36 numbers), not both.
Eigen::Matrix<double, 6, 6> ReadStiffness(const Field& section) {
  const Field full = section.Child("stiffness");
  Eigen::Matrix<double, 6, 6> C = Eigen::Matrix<double, 6, 6>::Zero();
  if (full.present()) {
    for (const char* key : kDiagonalKeys) {
      if (section.Child(key).present()) {
        section.Child(key).Fail("given together with 'stiffness'; expected one of them");
      }
    }
    const std::vector<double> values = ReadNumberList(full, Quantity{"a stiffness entry", Bound::kAny, ""});
    if (values.size() != 36) {
      full.Fail(std::to_string(values.size()) + " numbers; expected 36 (the 6x6 section stiffness, row by row)");
    }
    for (int i = 0; i < 36; ++i) C(i / 6, i % 6) = values[i];
    if (!C.isApprox(C.transpose(), 1e-12)) full.Fail("is not symmetric; expected a symmetric 6x6 matrix");
    return C;
  }
  for (int k = 0; k < 6; ++k) {
    RequireKey(section, kDiagonalKeys[k], std::string("the section stiffness ") + kDiagonalKeys[k] + " [" +
                                              kDiagonalUnits[k] + "] (or the full 6x6 'stiffness')");
    C(k, k) = ReadNumber(section.Child(kDiagonalKeys[k]),
                         Quantity{std::string("a stiffness ") + kDiagonalKeys[k], Bound::kPositive, kDiagonalUnits[k]});
  }
  return C;
}

// `offsets: {cg: [y, z], shear_center: [y, z]}` in the section frame [m].
void ReadOffsets(const Field& offsets, BeamSectionSpec* spec) {
  CheckKeys(offsets, kOffsetKeys);
  const std::pair<const char*, Eigen::Vector2d*> entries[] = {{"cg", &spec->cg_offset},
                                                              {"shear_center", &spec->shear_center_offset}};
  for (const auto& [key, value] : entries) {
    const Field field = offsets.Child(key);
    if (!field.present()) continue;
    const std::vector<double> yz = ReadNumberList(field, Quantity{"an offset", Bound::kAny, "m"});
    if (yz.size() != 2) {
      field.Fail(std::to_string(yz.size()) + " numbers; expected [y, z], the offset in the section frame [m]");
    }
    *value = Eigen::Vector2d(yz[0], yz[1]);
  }
}

void ReadSection(const Field& section, BeamSectionSpec* spec) {
  CheckKeys(section, kBeamSectionKeys);
  spec->stiffness = ReadStiffness(section);
  RequireKey(section, "m", "the mass per length m [kg/m]");
  spec->mass_per_length = ReadNumber(section.Child("m"), Quantity{"a mass per length", Bound::kPositive, "kg/m"});
  OverlayVec3(section, "m_ii",
              Quantity{"mass moments per length", Bound::kNonNegative, "kg m", "[torsional, about y, about z]"},
              &spec->inertia_per_length);
  if (section.Child("offsets").present()) ReadOffsets(section.Child("offsets"), spec);
}

void ReadBeam(const Field& beam, BeamSpec* spec) {
  CheckKeys(beam, kBeamKeys);
  RequireKey(beam, "length", "the beam length [m] along the link's x axis");
  spec->length = ReadNumber(beam.Child("length"), Quantity{"a length", Bound::kPositive, "m"});
  OverlayCount(beam, "elements", Quantity{"a number of elements", Bound::kAtLeastOne, ""}, kMaxBeamElements,
               "elements in one beam", &spec->elements);
  OverlayInteger(beam, "order", Quantity{"a shape-function order", Bound::kAtLeastOne, ""}, &spec->order);
  if (spec->order > 3) beam.Child("order").Fail(std::to_string(spec->order) + " is above 3; expected 1, 2 or 3");
  OverlayNumber(beam, "damping", Quantity{"a damping time mu", Bound::kNonNegative, "s"}, &spec->damping);
  RequireKey(beam, "section", "the section properties {EA, GA2, GA3, GJ, EI2, EI3 | stiffness, m, m_ii}");
  ReadSection(beam.Child("section"), &spec->section);
}
}  // namespace

std::set<std::string> BeamLinkNames(const YAML::Node& params, const std::string& params_name) {
  const Field beams = Field(params, params_name).Child("beams");
  std::set<std::string> names;
  if (!beams.present()) return names;
  for (const std::string& name : MapKeys(beams, "a map from URDF link names to beam settings")) names.insert(name);
  return names;
}

void ReadBeams(const Field& beams, UrdfModel* model) {
  for (const std::string& name : MapKeys(beams, "a map from URDF link names to beam settings")) {
    for (BeamSpec& spec : model->spec.beams) {
      if (spec.name == name) ReadBeam(beams.Child(name), &spec);
    }
  }
}

}  // namespace io
}  // namespace flexmbd
