// The velocity projection after jumps (docs/theory.md, "Velocity projection after jumps") against its closed
// form on a pendulum: the mass-weighted projection of the node's velocities onto the one motion the pivot
// allows, the kinetic energy it removes booked as numerical dissipation.

#include <gtest/gtest.h>

#include "flexmbd/effects/joint_stop.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/joint_rates.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "flexmbd/solver/velocity_projection.hpp"
#include "tangent_test_models.hpp"

namespace flexmbd {
namespace velocity_projection_test {

// The pivoted arm with a tight Newton tolerance.
ModelSpec Pendulum() {
  ModelSpec spec = test::PivotedArm("pendulum (unit test)");
  spec.solver.tol = 1.0e-12;
  return spec;
}

double Kinetic(const Model& model, const State& state, const Vec3& v, const Vec3& w) {
  State moved = state;
  moved.nodes[0].v = v;
  moved.nodes[0].w = w;
  EnergyTally energy;
  for (const auto& element : model.elements()) element->AddEnergy(moved, model.solver().gravity, &energy);
  return energy.kinetic;
}

TEST(VelocityProjection, IsTheMassWeightedProjectionOntoThePivotsMotion) {
  const Model model = BuildModel(Pendulum());
  SparseSystem system(model);
  VelocityProjection projection(model, &system);
  State state = model.initial_state();
  state.h_prev = 0.01;
  // Velocities the pivot does not allow: a node velocity with components along the arm and across the plane,
  // and a spin with components about x and z.
  const Vec3 v(0.3, -0.2, 1.1), w(0.4, 1.5, -0.7);
  state.nodes[0].v = v;
  state.nodes[0].w = w;
  const double kinetic_before = Kinetic(model, state, v, w);
  // The one allowed motion per unit rate, and the rate that minimises the kinetic energy of what is removed:
  // omega = <s, d>_M / <d, d>_M, the products taken from the kinetic energy by polarisation (it is quadratic).
  const Vec3 d_v = Vec3::UnitY().cross(state.nodes[0].x), d_w = state.nodes[0].R.transpose() * Vec3::UnitY();
  const double s_d = Kinetic(model, state, v + d_v, w + d_w) - kinetic_before - Kinetic(model, state, d_v, d_w);
  const double omega = s_d / (2.0 * Kinetic(model, state, d_v, d_w));
  ASSERT_TRUE(projection.Apply(&state, {}));  // no effects to hold
  // Extrapolated from steps of 1e-6 and 2e-6 s, the forces' share is O(h^2 g) ~ 1e-11 m/s; Newton at 1e-12.
  constexpr double kTolerance = 1.0e-9;
  EXPECT_NEAR((state.nodes[0].v - omega * d_v).norm(), 0.0, kTolerance);
  EXPECT_NEAR((state.nodes[0].w - omega * d_w).norm(), 0.0, kTolerance);
  EXPECT_NEAR(state.qdot[0], omega, kTolerance);
  // What was removed, (s - s*)^T M (s - s*) / 2, is booked; nothing else is.
  const double removed = Kinetic(model, state, v - omega * d_v, w - omega * d_w);
  EXPECT_GT(removed, 0.1);
  EXPECT_NEAR(state.dissipated_numerical, removed, kTolerance);
  EXPECT_NEAR(state.dissipated_numerical, kinetic_before - Kinetic(model, state, state.nodes[0].v, state.nodes[0].w),
              kTolerance);
  EXPECT_NEAR(state.external_work, 0.0, kTolerance);
  // Consistent velocities stay as they are.
  const State projected = state;
  ASSERT_TRUE(projection.Apply(&state, {}));  // no effects to hold
  EXPECT_NEAR((state.nodes[0].v - projected.nodes[0].v).norm(), 0.0, kTolerance);
  EXPECT_NEAR((state.nodes[0].w - projected.nodes[0].w).norm(), 0.0, kTolerance);
}

// At a jump of a drive's rate (docs/theory.md, "Jumps of a drive's rate") the driven arm's velocities, which carry
// a part the pivot does not allow, are carried from the drive's rate before to its rate after: the result is the
// one motion at the rate after; the books split into the scheme's removal of what the pivot does not allow and the
// drive's work, the change of the kinetic energy of the allowed motion.
TEST(VelocityProjection, CarriesADrivenArmAcrossAJumpOfItsRateAndBooksTheDrivesWork) {
  ModelSpec spec = Pendulum();
  spec.joints[0].effects[0].drives.push_back(TimeFunctionSpec());  // held at 0: the rates below replace it
  const Model model = BuildModel(spec);
  SparseSystem system(model);
  VelocityProjection projection(model, &system);
  State state = model.initial_state();
  constexpr double kBefore = 1.0, kAfter = -2.5;  // [rad/s]
  const Vec3 d_v = Vec3::UnitY().cross(state.nodes[0].x), d_w = state.nodes[0].R.transpose() * Vec3::UnitY();
  // The motion at the rate before, plus what the pivot does not allow (along the arm, across the plane; spins
  // about x and z) and some more of the allowed motion, which the drive does not allow either.
  const Vec3 junk_v = Vec3(0.3, 0.0, 1.1) + 0.2 * d_v, junk_w = Vec3(0.4, 0.0, -0.7) + 0.2 * d_w;
  state.nodes[0].v = kBefore * d_v + junk_v;
  state.nodes[0].w = kBefore * d_w + junk_w;
  const double kinetic_before = Kinetic(model, state, state.nodes[0].v, state.nodes[0].w);
  const Eigen::VectorXd before = Eigen::VectorXd::Constant(1, kBefore), after = Eigen::VectorXd::Constant(1, kAfter);
  ASSERT_TRUE(projection.ApplyAtDriveJump(&state, before, after, 0.01));
  // Limiting steps of 1e-6 and 2e-6 s, Newton at 1e-12: as in the projection above.
  constexpr double kTolerance = 1.0e-9;
  EXPECT_NEAR((state.nodes[0].v - kAfter * d_v).norm(), 0.0, kTolerance);
  EXPECT_NEAR((state.nodes[0].w - kAfter * d_w).norm(), 0.0, kTolerance);
  EXPECT_NEAR(state.qdot[0], kAfter, kTolerance);
  // Closed forms: the scheme removes the kinetic energy of the junk; the drive then takes the arm from the rate
  // before to the rate after, (kAfter^2 - kBefore^2) K(d).
  const double junk = Kinetic(model, state, junk_v, junk_w), unit = Kinetic(model, state, d_v, d_w);
  ASSERT_GT(junk, 0.1);
  EXPECT_NEAR(state.dissipated_numerical, junk, kTolerance);
  // The books close: what the kinetic energy gained is the external work less the numerical dissipation; of the
  // external work, the jump's share is the drive's (the rest is its impulse on the junk, at the rate before).
  EXPECT_NEAR(state.external_work - state.dissipated_numerical, kAfter * kAfter * unit - kinetic_before, kTolerance);
  const double on_the_junk = kBefore * kBefore * unit + junk - Kinetic(model, state, kBefore * d_v + junk_v,
                                                                        kBefore * d_w + junk_w);
  EXPECT_NEAR(state.external_work - on_the_junk, (kAfter * kAfter - kBefore * kBefore) * unit, kTolerance);
}

// A contact brought to rest (docs/theory.md, (C2a')): the arm swings into a rigid stop at its current angle. Held,
// the stop's constraint forbids the arm's one motion, so the projection stops it and books all its kinetic energy;
// released, the stop allows the motion and the projection keeps it.
TEST(VelocityProjection, HoldsAContactBroughtToRestAndReleasesTheOthers) {
  ModelSpec spec = Pendulum();
  StopSpec stop;
  stop.name = "upper";
  stop.side = StopSpec::Side::kUpper;
  spec.joints[0].effects[0].stops.push_back(stop);
  const Model model = BuildModel(spec);
  ASSERT_EQ(model.modal_effects().size(), 1u);
  const int slot = model.modal_effects()[0]->slot();
  SparseSystem system(model);
  VelocityProjection projection(model, &system);
  State state = model.initial_state();
  state.h_prev = 0.01;
  constexpr double kRate = 1.5;  // [rad/s], into the stop
  state.nodes[0].v = kRate * Vec3::UnitY().cross(state.nodes[0].x);
  state.nodes[0].w = kRate * state.nodes[0].R.transpose() * Vec3::UnitY();
  state.qdot = JointRates(model, state);
  state.effects[slot].mode = JointStop::kContact;
  const double kinetic_before = Kinetic(model, state, state.nodes[0].v, state.nodes[0].w);
  constexpr double kTolerance = 1.0e-9;  // as above

  State released = state;
  ASSERT_TRUE(projection.Apply(&released, {false}));
  EXPECT_NEAR(released.qdot[0], kRate, kTolerance);
  EXPECT_NEAR(released.dissipated_numerical, 0.0, kTolerance);
  EXPECT_EQ(released.effects[slot].mode, JointStop::kContact);  // the state keeps its modes

  ASSERT_TRUE(projection.Apply(&state, {true}));
  EXPECT_NEAR(state.qdot[0], 0.0, kTolerance);
  EXPECT_NEAR(state.nodes[0].v.norm(), 0.0, kTolerance);
  EXPECT_NEAR(state.nodes[0].w.norm(), 0.0, kTolerance);
  EXPECT_GT(kinetic_before, 1.0);
  EXPECT_NEAR(state.dissipated_numerical, kinetic_before, kTolerance);
}

}  // namespace velocity_projection_test
}  // namespace flexmbd
