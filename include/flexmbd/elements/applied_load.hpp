#pragma once
/// @file
/// A force or moment applied to a node, dead (fixed in W) or follower (fixed in the body), scaled by a time
/// function taken at mid-step. A dead force at an offset d uses the exact change of the point's position,
/// dx - R_i Skew(S d) theta, so its work over a step is exactly F . (change of the point).

#include "flexmbd/elements/element.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

class AppliedLoad : public Element {
 public:
  /// @param p_NP_N point of application relative to the node, in the node frame [m].
  AppliedLoad(int node, int first_unknown, const LoadSpec& spec, const Vec3& p_NP_N);

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;

 private:
  // Generalised force conjugate to (dx, theta) over the step, for the node's step n.
  Vec6 GeneralisedForce(const StepContext& ctx, const NodeStep& n) const;

  int node_;
  LoadSpec spec_;
  Vec3 p_NP_N_;
};

}  // namespace flexmbd
