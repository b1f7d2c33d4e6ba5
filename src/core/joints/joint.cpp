#include "flexmbd/joints/joint.hpp"

#include <cmath>

#include "flexmbd/common/error.hpp"
#include "flexmbd/math/discrete_path.hpp"

namespace flexmbd {
namespace {
// Relative finite-difference step for the geometric stiffness; sqrt(machine epsilon) balances truncation
// against round-off for a forward difference.
constexpr double kFiniteDifferenceStep = 1.5e-8;

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
  for (const Attachment* side : {&parent_, &child_}) {
    if (OnNode(*side)) {
      for (int k = 0; k < 6; ++k) unknowns_.push_back(side->first_unknown + k);
    }
  }
  for (int k = 0; k < kinematics_.num_variables; ++k) unknowns_.push_back(first_variable_unknown + k);
  num_increments_ = num_local();
  for (int k = 0; k < num_constraints_; ++k) unknowns_.push_back(first_multiplier_unknown + k);
}

void Joint::GatherSides(const StepContext& ctx, std::vector<NodeStep>* sides, Eigen::VectorXd* q_i,
                        Eigen::VectorXd* q_f) const {
  sides->clear();
  for (const Attachment* side : {&parent_, &child_}) {
    if (OnNode(*side)) sides->push_back((*ctx.nodes)[side->node]);
  }
  const int n = kinematics_.num_variables;
  q_i->resize(n);
  q_f->resize(n);
  for (int k = 0; k < n; ++k) {
    (*q_i)[k] = (*ctx.variables)[first_variable_ + k].q_i;
    (*q_f)[k] = (*ctx.variables)[first_variable_ + k].q_f;
  }
}

Joint::Evaluation Joint::Evaluate(const std::vector<NodeStep>& sides, const Eigen::VectorXd& q_i,
                                  const Eigen::VectorXd& q_f) const {
  const int n = num_increments_;
  // Node paths (increments dx then theta, 6 per node side); a world side is a constant frame.
  auto rotation = [&](const Attachment& side, int slot) {
    return OnNode(side) ? NodeRotationPath(sides[slot], 6 * slot + 3) : ConstantPath<3>(Mat3::Identity());
  };
  auto position = [&](const Attachment& side, int slot) {
    return OnNode(side) ? NodePositionPath(sides[slot], 6 * slot) : ConstantPath<1>(Vec3::Zero());
  };
  const int parent_slot = 0, child_slot = OnNode(parent_) ? 1 : 0;
  const int offset = 6 * static_cast<int>(sides.size());  // first joint variable
  const MatrixPath R_a = rotation(parent_, parent_slot), R_b = rotation(child_, child_slot);
  const VectorPath x_a = position(parent_, parent_slot), x_b = position(child_, child_slot);

  const MatrixPath R_aJp = ConstantPath<3>(parent_.R_NJ);
  const VectorPath t = LinearPath(kinematics_.translation_rates_Jp, q_i, q_f, offset);
  const VectorPath p_Jp = ConstantPath<1>(parent_.p_NJ) + R_aJp * t;
  const VectorPath phi_p = x_b + R_b * ConstantPath<1>(child_.p_NJ) - x_a - R_a * p_Jp;

  Evaluation e;
  e.phi.resize(num_constraints_);
  e.G.resize(num_constraints_, n);
  e.D.resize(num_constraints_, n);
  e.phi.head<3>() = phi_p.f;
  for (int k = 0; k < n; ++k) {
    e.G.block<3, 1>(0, k) = phi_p.gradient(k);
    e.D.block<3, 1>(0, k) = phi_p.derivative(k);
  }
  if (!kinematics_.rotation_constrained) return e;

  MatrixPath rel = ConstantPath<3>(Mat3::Identity());
  for (const RotationFactor& factor : kinematics_.rotations) {
    rel = rel * AxisRotationPath(factor.axis_J, q_i[factor.variable], q_f[factor.variable], offset + factor.variable);
  }
  const MatrixPath C =
      Transpose(rel) * (Transpose(R_aJp) * (Transpose(R_a) * (R_b * ConstantPath<3>(child_.R_NJ))));
  e.phi.tail<3>() = Axial(C.f);
  for (int k = 0; k < n; ++k) {
    e.G.block<3, 1>(3, k) = Axial(C.gradient(k));
    e.D.block<3, 1>(3, k) = Axial(C.derivative(k));
  }
  return e;
}

Joint::Evaluation Joint::EvaluateAt(const StepContext& ctx) const {
  std::vector<NodeStep> sides;
  Eigen::VectorXd q_i, q_f;
  GatherSides(ctx, &sides, &q_i, &q_f);
  return Evaluate(sides, q_i, q_f);
}

Eigen::VectorXd Joint::Multipliers(const StepContext& ctx) const {
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
  std::vector<NodeStep> sides;
  Eigen::VectorXd q_i, q_f;
  GatherSides(ctx, &sides, &q_i, &q_f);
  const Evaluation e = Evaluate(sides, q_i, q_f);
  const Eigen::VectorXd lambda = Multipliers(ctx);
  const int n = num_increments_;
  r.head(n) += e.G.transpose() * lambda;
  magnitude.head(n) += e.G.cwiseAbs().transpose() * lambda.cwiseAbs();
  r.tail(num_constraints_) += e.phi;
  if (J == nullptr) return;
  J->block(0, n, n, num_constraints_) += e.G.transpose();
  J->block(n, 0, num_constraints_, n) += e.D;
  if (!ctx.geometric_stiffness) return;
  // d(G^T lambda)/d(increments) by forward differences of the analytic G.
  const Eigen::VectorXd base = e.G.transpose() * lambda;
  const int node_increments = 6 * static_cast<int>(sides.size());
  for (int k = 0; k < n; ++k) {
    std::vector<NodeStep> moved = sides;
    Eigen::VectorXd q_f_moved = q_f, q_i_moved = q_i;
    if (k < node_increments) {
      Vec6 d = Vec6::Zero();
      d[k % 6] = kFiniteDifferenceStep;
      moved[k / 6] = PerturbNodeStep(sides[k / 6], d, ctx.mode);
    } else {
      q_f_moved[k - node_increments] += kFiniteDifferenceStep;
      if (ctx.at_end()) q_i_moved[k - node_increments] += kFiniteDifferenceStep;
    }
    const Evaluation moved_e = Evaluate(moved, q_i_moved, q_f_moved);
    J->block(0, k, n, 1) += (moved_e.G.transpose() * lambda - base) / kFiniteDifferenceStep;
  }
}

Eigen::VectorXd Joint::ConstraintValues(const StepContext& ctx) const { return EvaluateAt(ctx).phi; }

Eigen::VectorXd Joint::VariableForces(const StepContext& ctx) const {
  const Evaluation e = EvaluateAt(ctx);
  const int n_var = kinematics_.num_variables;
  return e.G.rightCols(n_var).transpose() * Multipliers(ctx);
}

}  // namespace flexmbd
