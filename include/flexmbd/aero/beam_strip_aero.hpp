#pragma once
/// @file
/// One strip of thin-airfoil loads on a beam node (docs/theory.md, (A7)-(A9)): the air's velocity relative to
/// the node, resolved in the node's section frame, gives the chordwise speed u, the normal velocity v and the
/// pitch rate of the strip (the spanwise component is dropped: strip theory); Theodorsen's lift and moment about
/// the beam axis (the elastic axis) in their general form, with Peters' inflow states of the strip's own, act on
/// the node over the node's lumped length.

#include <string>

#include "flexmbd/aero/peters_inflow.hpp"
#include "flexmbd/aero/typical_section_aero.hpp"
#include "flexmbd/elements/element.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

class BeamStripAero : public Element {
 public:
  /// @param node the beam node; its unknowns start at node_unknown. @param length the strip's span [m].
  /// @param first_state_unknown the unknown of the strip's first inflow state.
  BeamStripAero(const AeroStripSpec& spec, const AeroFlowSpec& flow, int node, int node_unknown, double length,
                int first_state_unknown);

  int num_states() const override { return inflow_.b.size(); }
  double StateScale(int) const override { return scale_; }
  std::string StateName(int k) const override { return "mu_" + std::to_string(k + 1); }
  std::string StateOwnerName() const override { return "aero strip " + name_; }

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  bool HasRateParts(AnalysisMode mode) const override { return mode != AnalysisMode::kStatic; }
  void AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D, Eigen::Ref<Eigen::MatrixXd> M) const override;
  /// The air's work on the node over a step: external work.
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;

  /// Lift [N] along the chord normal and moment [N m] nose up about the beam axis, over the strip, at ctx.
  Eigen::Vector2d StripLoads(const StepContext& ctx) const;

 private:
  using States = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxInflowStates, 1>;
  // What the loads read at ctx: the section frame, the air's velocity relative to the node in it (V), the
  // node's angular velocity (w) and the rates of both (Vdot, wdot) in the section frame, the inflow states.
  struct Motion {
    Mat3 R, turn;  // section frame in W; its change per unit rotation increment
    Vec3 V, w, Vdot, wdot;
    States mu, mu_rate;
  };
  // The loads and their gradients with respect to V, w, Vdot, wdot (section frame) and mu.
  struct Loads {
    double u = 0, w34 = 0, lift = 0, moment = 0;
    Eigen::Matrix<double, 1, 3> du_dV, dw34_dV, dw34_dw;
    Eigen::Matrix<double, 2, 3> dV, dw, dVdot, dwdot;  // rows: lift, moment
    Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, kMaxInflowStates> dmu;
  };
  Motion MotionAt(const StepContext& ctx) const;
  Loads Compute(const Motion& m) const;
  // The forces on the node's unknowns: [force in W; moment in the section frame] over the strip.
  Vec6 NodeForces(const Motion& m, const Loads& loads) const;

  std::string name_;
  int node_;
  double semichord_, a_, length_, density_;
  Vec3 chord_, normal_, pitch_axis_;  ///< section frame; pitch_axis = normal x chord turns the nose up
  Vec3 free_stream_, gust_;
  TimeFunctionSpec gust_scale_;
  PetersInflow inflow_;
  Eigen::VectorXd lag_;  ///< Abar^-1 cbar: lambda - mu per unit w34
  double lag0_ = 0;      ///< bbar^T Abar^-1 cbar / 2: lambda0 - bbar^T mu / 2 per unit w34
  double scale_;         ///< size of the states [m/s]
};

}  // namespace flexmbd
