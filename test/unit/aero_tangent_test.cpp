// The typical-section aerodynamic element's analytic tangent (docs/theory.md, (A6)) against central differences
// of its residual: the whole scheme tangent of a mid-step (energy-decaying) step, and at the end point its
// stiffness part and its rate parts.

#include <gtest/gtest.h>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "scheme_tangent_check.hpp"

namespace flexmbd {
namespace aero_tangent_test {

// The residual is linear in every unknown but the node rotations (whose rates enter through w = T theta / h),
// so central differences with steps of 1e-6 are exact to round-off, ~1e-16 |r| / 1e-6 = 1e-10 of the largest
// entry; 1e-7 leaves room.
constexpr double kStep = 1.0e-6, kTolerance = 1.0e-7;

struct Section {
  Model model;
  const TypicalSectionAero* element;
  State start;
};

Section ConnerSection() {
  const std::string dir = std::string(FLEXMBD_SOURCE_DIR) + "/config/conner_section/";
  ModelSpec spec = LoadModelSpec(dir + "conner_section.urdf", dir + "flutter_below.yaml");
  spec.aero_sections.at(0).inflow_states = 4;
  Section s{BuildModel(spec), nullptr, State()};
  s.element = s.model.aero_sections().at(0);
  s.start = s.model.initial_state();
  test::Random random(7);
  for (NodeState& n : s.start.nodes) {
    n.v = random.Vector(0.5);
    n.w = random.Vector(2.0);
  }
  s.start.element_states = Eigen::VectorXd::LinSpaced(4, 0.3, -0.2);
  s.start.element_state_rates = Eigen::VectorXd::LinSpaced(4, 1.0, 2.0);
  return s;
}

TEST(AeroTangent, MidStepSchemeTangentMatchesDifferences) {
  const Section s = ConnerSection();
  test::ExpectMidStepTangentMatchesDifferences(s.model, *s.element, s.start, kStep, kTolerance);
}

TEST(AeroTangent, EndPointStiffnessAndRatePartsMatchDifferences) {
  const Section s = ConnerSection();
  test::ExpectEndPointPartsMatchDifferences(s.model, *s.element, s.start, 0.0, 0.5, kStep, kStep, kTolerance);
}

}  // namespace aero_tangent_test
}  // namespace flexmbd
