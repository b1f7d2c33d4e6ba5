#pragma once
/// @file
/// A lower-pair joint between a frame Jp on a parent node (or the world) and a frame Jc on a child node,
/// with its relative-motion variables q as explicit unknowns (docs/theory.md, eqs. (T7)-(T9)):
///   position  p_WJc - p_WJp - R_WJp t(q) = 0            (3 rows, multipliers = force on Jp side, in W)
///   rotation  Axial(Rel(q)^T R_WJp^T R_WJc) = 0         (3 rows; absent for a spherical joint)
/// The constraint forces are G^T lambda with G the exact discrete gradient of these rows over the step, so
/// they do zero work when the rows hold at both ends of the step.

#include <array>
#include <string>

#include <Eigen/Core>

#include "flexmbd/elements/element.hpp"
#include "flexmbd/joints/joint_kinematics.hpp"
#include "flexmbd/math/discrete_path.hpp"

namespace flexmbd {

class Joint : public Element {
 public:
  /// Where one side of the joint is fixed. node < 0 means the world; p_NJ, R_NJ are then the pose in W.
  struct Attachment {
    int node = -1;
    int first_unknown = -1;  ///< global index of the node's first unknown
    Vec3 p_NJ = Vec3::Zero();
    Mat3 R_NJ = Mat3::Identity();
  };

  /// @param first_variable index of the joint's first variable in State::q; its unknowns start at
  /// first_variable_unknown. @param first_multiplier index into State::lambda, unknowns at first_multiplier_unknown.
  Joint(std::string name, const Attachment& parent, const Attachment& child, JointKinematics kinematics,
        int first_variable, int first_variable_unknown, int first_multiplier, int first_multiplier_unknown);

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void AddResidualAndTangent(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                             Eigen::Ref<Eigen::VectorXd> magnitude, Eigen::Ref<Eigen::MatrixXd>* J) const override;

  /// Constraint rows at the end of the step (size num_constraints) [m, rad].
  Eigen::VectorXd ConstraintValues(const StepContext& ctx) const;

  /// Generalised force the joint transmits along each variable, (G_q^T lambda) [N m or N]: the sum of the
  /// spring, damper, drive and commanded forces acting on the child along that variable.
  Eigen::VectorXd VariableForces(const StepContext& ctx) const;

  const std::string& name() const { return name_; }
  int num_variables() const { return kinematics_.num_variables; }
  int num_constraints() const { return num_constraints_; }
  int first_variable() const { return first_variable_; }
  int first_multiplier() const { return first_multiplier_; }
  const JointKinematics& kinematics() const { return kinematics_; }
  const Attachment& parent() const { return parent_; }
  const Attachment& child() const { return child_; }

 private:
  static constexpr int kMaxVariables = 3;  ///< a planar joint's
  using Variables = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxVariables, 1>;
  using ConstraintVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
  using ConstraintMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, MatrixPath::kMaxIncrements>;
  using IncrementVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, MatrixPath::kMaxIncrements, 1>;

  // The joint's part of a step: its node sides (parent first; a world side has none) and variables.
  struct Sides {
    std::array<NodeStep, 2> nodes;
    int num_nodes = 0;
    Variables q_i, q_f;
  };
  // Constraint rows at f, their exact discrete gradient G and, if asked for, their derivative D w.r.t. the
  // local increments. Fixed capacity: evaluating allocates nothing.
  // With a direction, also the variation of G along that increment (G_variation).
  struct Evaluation {
    ConstraintVector phi;
    ConstraintMatrix G, D, G_variation;
  };
  Evaluation Evaluate(const Sides& sides, bool with_derivative, const PathDirection& direction = {}) const;
  Sides GatherSides(const StepContext& ctx) const;
  Eigen::Ref<const Eigen::VectorXd> Multipliers(const StepContext& ctx) const;  ///< a view into ctx.lambda

  std::string name_;
  Attachment parent_, child_;
  JointKinematics kinematics_;
  int first_variable_, first_multiplier_;
  int num_constraints_;
  int num_increments_;  ///< local node and variable increments (multipliers follow them)
};

}  // namespace flexmbd
