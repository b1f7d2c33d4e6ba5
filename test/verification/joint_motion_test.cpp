// Every joint type under loads: constrained relative motions stay at round-off and the free ones follow the
// hand-derived solution (a body starting at rest under constant loads, no gravity).

#include <gtest/gtest.h>

#include <cmath>

#include "case_builders.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "flexmbd/solver/step_context_builder.hpp"

namespace flexmbd {
namespace joint_motion_test {

constexpr double kMass = 2.0, kInertia = 0.5;  // body mass [kg], isotropic inertia about the CM [kg m^2]
constexpr double kForce = 3.0, kMoment = 0.7;  // loads along/about the joint axis [N], [N m]
constexpr double kTime = 1.0;
// Constraints are solved to kConstraintTolerance = 1e-11 at every step.
constexpr double kConstraintLimit = 1.0e-10;
// Constant loads from rest give quadratic motion, which the trapezoidal-family scheme integrates exactly;
// 1e-9 leaves room for the Newton tolerance (1e-12) accumulated over the steps.
constexpr double kMotionTolerance = 1.0e-9;

// One body (CM at the joint, no offset) on a joint of the given type to the world, axis z, with a force
// along z and a moment about z applied, plus off-axis loads that only the constraints must resist.
ModelSpec SingleJointCase(JointType type) {
  ModelSpec spec;
  spec.source = "joint motion (test)";
  BodySpec body;
  body.name = "body";
  body.mass = kMass;
  body.inertia_cm_B = kInertia * Mat3::Identity();
  spec.bodies.push_back(body);
  JointSpec joint;
  joint.name = "joint";
  joint.type = type;
  joint.child = "body";
  joint.axis_J = Vec3::UnitZ();
  joint.axis2_J = Vec3::UnitX();
  joint.pitch = 0.1;
  spec.joints.push_back(joint);
  auto load = [&](LoadSpec::Kind kind, const Vec3& v) {
    LoadSpec l;
    l.body = "body";
    l.kind = kind;
    l.vector = v;
    spec.loads.push_back(l);
  };
  load(LoadSpec::Kind::kForce, Vec3(0.4, -0.3, kForce));
  load(LoadSpec::Kind::kMoment, Vec3(-0.2, 0.5, kMoment));
  spec.solver.gravity = Vec3::Zero();
  spec.solver.adaptive = false;
  spec.solver.integrator = SolverSpec::Integrator::kEnergyPreserving;
  spec.solver.dt = 1.0e-2;
  spec.solver.t_end = kTime;
  spec.solver.tol = 1.0e-12;
  spec.output.rate_hz = 0;
  return spec;
}

struct Outcome {
  Eigen::VectorXd q;
  double max_constraint = 0;
  double energy_error = 0;  // |E - E0 - W_ext| at the end [J]
};

Outcome RunJoint(JointType type) {
  const Model model = BuildModel(SingleJointCase(type));
  Simulation simulation(model);
  Outcome out;
  StepContextBuilder builder(model);
  OutputSample first, last;
  bool have_first = false;
  simulation.Run([&](const OutputSample& s) {
    if (!have_first) first = s, have_first = true;
    last = s;
    const double violation =
        model.joints()[0]->ConstraintValues(builder.AtState(simulation.state())).cwiseAbs().maxCoeff();
    out.max_constraint = std::max(out.max_constraint, violation);
  });
  out.q = simulation.state().q;
  out.energy_error = std::abs(last.total() - first.total() - last.external_work);
  return out;
}

double Quadratic(double load, double inertia) { return 0.5 * load / inertia * kTime * kTime; }

TEST(JointMotion, RevoluteTurnsUnderAxialMoment) {
  const Outcome o = RunJoint(JointType::kRevolute);
  EXPECT_LT(o.max_constraint, kConstraintLimit);
  EXPECT_NEAR(o.q[0], Quadratic(kMoment, kInertia), kMotionTolerance);
}

TEST(JointMotion, PrismaticSlidesUnderAxialForce) {
  const Outcome o = RunJoint(JointType::kPrismatic);
  EXPECT_LT(o.max_constraint, kConstraintLimit);
  EXPECT_NEAR(o.q[0], Quadratic(kForce, kMass), kMotionTolerance);
}

TEST(JointMotion, CylindricalTurnsAndSlidesIndependently) {
  const Outcome o = RunJoint(JointType::kCylindrical);
  EXPECT_LT(o.max_constraint, kConstraintLimit);
  EXPECT_NEAR(o.q[0], Quadratic(kMoment, kInertia), kMotionTolerance);
  EXPECT_NEAR(o.q[1], Quadratic(kForce, kMass), kMotionTolerance);
}

TEST(JointMotion, ScrewCouplesTurnAndAdvance) {
  // s = c phi with c = pitch / 2 pi: generalised inertia J + m c^2, generalised force M + F c.
  const Outcome o = RunJoint(JointType::kScrew);
  const double c = 0.1 / (2 * M_PI);
  EXPECT_LT(o.max_constraint, kConstraintLimit);
  EXPECT_NEAR(o.q[0], Quadratic(kMoment + kForce * c, kInertia + kMass * c * c), kMotionTolerance);
}

TEST(JointMotion, PlanarMovesInPlaneOnly) {
  // Variables (phi about z, x, y in the plane); in-plane force (0.4, -0.3) and moment about z.
  const Outcome o = RunJoint(JointType::kPlanar);
  EXPECT_LT(o.max_constraint, kConstraintLimit);
  EXPECT_NEAR(o.q[0], Quadratic(kMoment, kInertia), kMotionTolerance);
  EXPECT_NEAR(o.q[1], Quadratic(0.4, kMass), kMotionTolerance);
  EXPECT_NEAR(o.q[2], Quadratic(-0.3, kMass), kMotionTolerance);
}

TEST(JointMotion, SphericalKeepsCentreAndConservesEnergy) {
  // Free rotation about a fixed point: work of the moment equals the gain of kinetic energy.
  const Outcome o = RunJoint(JointType::kSpherical);
  EXPECT_LT(o.max_constraint, kConstraintLimit);
  constexpr double kEnergyTolerance = 1.0e-9;  // exact discrete energy identity, Newton tolerance 1e-12
  EXPECT_LT(o.energy_error, kEnergyTolerance);
}

TEST(JointMotion, UniversalKeepsConstraintsAndConservesEnergy) {
  const Outcome o = RunJoint(JointType::kUniversal);
  EXPECT_LT(o.max_constraint, kConstraintLimit);
  constexpr double kEnergyTolerance = 1.0e-9;
  EXPECT_LT(o.energy_error, kEnergyTolerance);
}

TEST(JointMotion, FixedDoesNotMove) {
  const Outcome o = RunJoint(JointType::kFixed);
  EXPECT_LT(o.max_constraint, kConstraintLimit);
  EXPECT_EQ(o.q.size(), 0);
}

}  // namespace joint_motion_test
}  // namespace flexmbd
