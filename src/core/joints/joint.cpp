#include "flexmbd/joints/joint.hpp"

#include <cmath>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace {
bool OnNode(const Joint::Attachment& side) { return side.node >= 0; }
}  // namespace

Joint::Joint(std::string name, const Attachment& parent, const Attachment& child, JointKinematics kinematics,
             int first_variable, int first_variable_unknown, int first_multiplier, int first_multiplier_unknown)
    : name_(std::move(name)),
      parent_(parent),
      child_(child),
      kinematics_(std::move(kinematics)),
      first_variable_(first_variable),
      first_multiplier_(first_multiplier),
      num_constraints_(kinematics_.rotation_constrained ? 6 : 3) {
  FLEXMBD_DEMAND(OnNode(child_));
  FLEXMBD_DEMAND(kinematics_.num_variables <= kMaxVariables);
  for (const Attachment* side : {&parent_, &child_}) {
    if (OnNode(*side)) {
      for (int k = 0; k < 6; ++k) unknowns_.push_back(side->first_unknown + k);
    }
  }
  for (int k = 0; k < kinematics_.num_variables; ++k) unknowns_.push_back(first_variable_unknown + k);
  num_increments_ = num_local();
  for (int k = 0; k < num_constraints_; ++k) unknowns_.push_back(first_multiplier_unknown + k);
}

Joint::Sides Joint::GatherSides(const StepContext& ctx) const {
  Sides sides;
  for (const Attachment* side : {&parent_, &child_}) {
    if (OnNode(*side)) sides.nodes[sides.num_nodes++] = (*ctx.nodes)[side->node];
  }
  const int n = kinematics_.num_variables;
  sides.q_i.resize(n);
  sides.q_f.resize(n);
  for (int k = 0; k < n; ++k) {
    sides.q_i[k] = (*ctx.variables)[first_variable_ + k].q_i;
    sides.q_f[k] = (*ctx.variables)[first_variable_ + k].q_f;
  }
  return sides;
}

Joint::Evaluation Joint::Evaluate(const Sides& sides, bool with_derivative, const PathDirection& direction) const {
  const int n = num_increments_;
  // Node and variable paths (node increments dx then theta, 6 per node side; then the variables); a world
  // side is a constant frame. Without derivatives no path built from these keeps df.
  auto rotation = [&](const Attachment& side, int slot) {
    return OnNode(side) ? NodeRotationPath(sides.nodes[slot], 6 * slot + 3, direction)
                        : ConstantPath<3>(Mat3::Identity());
  };
  auto position = [&](const Attachment& side, int slot) {
    return OnNode(side) ? NodePositionPath(sides.nodes[slot], 6 * slot, direction) : ConstantPath<1>(Vec3::Zero());
  };
  const int parent_slot = 0, child_slot = OnNode(parent_) ? 1 : 0;
  const int offset = 6 * sides.num_nodes;  // first joint variable
  MatrixPath R_a = rotation(parent_, parent_slot), R_b = rotation(child_, child_slot);
  VectorPath x_a = position(parent_, parent_slot), x_b = position(child_, child_slot);
  VectorPath t = LinearPath(kinematics_.translation_rates_Jp, sides.q_i, sides.q_f, offset, direction);
  R_a.has_derivative = R_b.has_derivative = x_a.has_derivative = x_b.has_derivative = t.has_derivative =
      with_derivative;

  const MatrixPath R_aJp = ConstantPath<3>(parent_.R_NJ);
  const VectorPath p_Jp = ConstantPath<1>(parent_.p_NJ) + R_aJp * t;
  const VectorPath phi_p = x_b + R_b * ConstantPath<1>(child_.p_NJ) - x_a - R_a * p_Jp;

  Evaluation e;
  e.phi.resize(num_constraints_);
  e.G.resize(num_constraints_, n);
  if (with_derivative) e.D.resize(num_constraints_, n);
  const bool varied = direction.index >= 0;
  if (varied) e.G_variation.setZero(num_constraints_, n);
  e.phi.head<3>() = phi_p.f;
  for (int k = 0; k < n; ++k) {
    e.G.block<3, 1>(0, k) = phi_p.gradient(k);
    if (with_derivative) e.D.block<3, 1>(0, k) = phi_p.derivative(k);
    if (varied && phi_p.has_variation && phi_p.depends_on(k)) e.G_variation.block<3, 1>(0, k) = phi_p.vdg[k];
  }
  if (!kinematics_.rotation_constrained) return e;

  MatrixPath rel = ConstantPath<3>(Mat3::Identity());
  for (const RotationFactor& factor : kinematics_.rotations) {
    const int v = factor.variable;
    MatrixPath axis_rotation = AxisRotationPath(factor.axis_J, sides.q_i[v], sides.q_f[v], offset + v, direction);
    axis_rotation.has_derivative = with_derivative;
    rel = rel * axis_rotation;
  }
  const MatrixPath C =
      TransposeTimes(rel, TransposeTimes(R_aJp, TransposeTimes(R_a, R_b * ConstantPath<3>(child_.R_NJ))));
  e.phi.tail<3>() = Axial(C.f);
  for (int k = 0; k < n; ++k) {
    e.G.block<3, 1>(3, k) = Axial(C.gradient(k));
    if (with_derivative) e.D.block<3, 1>(3, k) = Axial(C.derivative(k));
    if (varied && C.has_variation && C.depends_on(k)) e.G_variation.block<3, 1>(3, k) = Axial(C.vdg[k]);
  }
  return e;
}

Eigen::Ref<const Eigen::VectorXd> Joint::Multipliers(const StepContext& ctx) const {
  return ctx.lambda->segment(first_multiplier_, num_constraints_);
}

void Joint::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                        Eigen::Ref<Eigen::VectorXd> magnitude) const {
  AddResidualAndTangent(ctx, r, magnitude, nullptr);
}

void Joint::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(num_local()), magnitude = Eigen::VectorXd::Zero(num_local());
  AddResidualAndTangent(ctx, r, magnitude, &J);
}

void Joint::AddResidualAndTangent(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                                  Eigen::Ref<Eigen::VectorXd> magnitude, Eigen::Ref<Eigen::MatrixXd>* J) const {
  const Sides sides = GatherSides(ctx);
  const Evaluation e = Evaluate(sides, /*with_derivative=*/J != nullptr);
  const Eigen::Ref<const Eigen::VectorXd> lambda = Multipliers(ctx);
  const int n = num_increments_;
  const IncrementVector force = e.G.transpose() * lambda;
  r.head(n) += force;
  // Evaluated into fixed-capacity storage first: Eigen would copy the expression |lambda| to the heap.
  const ConstraintVector lambda_abs = lambda.cwiseAbs();
  magnitude.head(n) += e.G.cwiseAbs().transpose() * lambda_abs;
  r.tail(num_constraints_) += e.phi;
  if (J == nullptr) return;
  J->block(0, n, n, num_constraints_) += e.G.transpose();
  J->block(n, 0, num_constraints_, n) += e.D;
  if (!ctx.geometric_stiffness) return;
  // d(G^T lambda)/d(increment k): the exact variation of every discrete gradient along increment k
  // (docs/theory.md, "Geometric stiffness of constraints"). Node translations enter the rows only through
  // x_b - x_a, whose discrete gradient is the identity whatever the step, so G does not vary along them.
  for (int k = 0; k < n; ++k) {
    const bool node_translation = k < 6 * sides.num_nodes && k % 6 < 3;
    if (node_translation) continue;
    const Evaluation varied = Evaluate(sides, /*with_derivative=*/false, PathDirection{k, ctx.at_end()});
    J->block(0, k, n, 1) += varied.G_variation.transpose() * lambda;
  }
}

Eigen::VectorXd Joint::ConstraintValues(const StepContext& ctx) const {
  return Evaluate(GatherSides(ctx), /*with_derivative=*/false).phi;
}

Eigen::VectorXd Joint::VariableForces(const StepContext& ctx) const {
  const Evaluation e = Evaluate(GatherSides(ctx), /*with_derivative=*/false);
  const int n_var = kinematics_.num_variables;
  return e.G.rightCols(n_var).transpose() * Multipliers(ctx);
}

}  // namespace flexmbd
