// The typical-section aerodynamic element's analytic tangent (docs/theory.md, (A6)) against central differences
// of its residual: the whole scheme tangent of a mid-step (energy-decaying) step, and at the end point its
// stiffness part and its rate parts.

#include <gtest/gtest.h>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "scheme_tangent_check.hpp"

namespace flexmbd {
namespace {

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
  StepContextBuilder builder(s.model);
  auto context = [&](const Eigen::VectorXd& u) -> const StepContext& {
    StepContext& ctx = builder.EndPoint(s.start, u, 0.0, 1.0e-3);
    test::Random random(7);
    for (NodeStep& n : builder.nodes()) {
      n.v_f = random.Vector(0.5);
      n.w_f = random.Vector(2.0);
      n.vdot_f = random.Vector(10.0);
      n.wdot_f = random.Vector(30.0);
    }
    return ctx;
  };
  const Eigen::VectorXd u = test::SomeIncrements(s.model);
  const StepContext& ctx = context(u);
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(s.element->num_local(), s.element->num_local());
  s.element->AddTangent(ctx, stiffness);
  const Eigen::MatrixXd expected = test::UnknownDifferences(*s.element, u, context, kStep);
  EXPECT_LT(test::MaxAbs(stiffness - expected), kTolerance * test::MaxAbs(expected));
  const test::RateParts parts = test::LocalRateParts(*s.element, context(u));
  for (bool accelerations : {false, true}) {
    const Eigen::MatrixXd differences = test::RateDifferences(*s.element, context(u), accelerations, kStep);
    const Eigen::MatrixXd& analytic = accelerations ? parts.M : parts.D;
    EXPECT_LT(test::MaxAbs(analytic - differences), kTolerance * test::MaxAbs(differences))
        << (accelerations ? "M" : "D");
  }
}

}  // namespace
}  // namespace flexmbd
