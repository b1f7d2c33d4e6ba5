#pragma once
/// @file
/// Rigid body with its node at the centre of mass (docs/theory.md, eqs. (T4)-(T5)):
///   m (v_f - v_i)/h - m g = 0                         (translation)
///   (Exp(theta) J w_f - J w_i)/h = 0                  (rotation, node frame at i)
/// plus the generalised forces that other elements add to the same rows. The kinetic energy changes by
/// exactly the work of those forces over (dx, theta) minus the scheme's dissipation (theory eq. (T6)).

#include "flexmbd/elements/element.hpp"

namespace flexmbd {

class RigidBody : public Element {
 public:
  /// @param node index of the node at the centre of mass; @param first_unknown its first global unknown.
  RigidBody(int node, int first_unknown, double mass, const Mat3& inertia_cm);

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  bool HasRateParts(AnalysisMode mode) const override;
  void AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                    Eigen::Ref<Eigen::MatrixXd> M) const override;
  void AddEnergy(const State& state, const Vec3& gravity, EnergyTally* tally) const override;

  int node() const { return node_; }
  double mass() const { return mass_; }
  const Mat3& inertia() const { return inertia_; }

 private:
  int node_;
  double mass_;   ///< [kg]
  Mat3 inertia_;  ///< about the centre of mass, node frame [kg m^2]
};

}  // namespace flexmbd
