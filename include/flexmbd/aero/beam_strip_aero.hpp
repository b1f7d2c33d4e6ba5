#pragma once
/// @file
/// One strip of thin-airfoil loads on a beam node (docs/theory.md, (A7)-(A10)): the air's velocity relative to
/// the node, resolved in the node's section frame, gives the chordwise speed u, the normal velocity v and the
/// pitch rate of the strip (the spanwise component is dropped: strip theory); Theodorsen's lift and moment about
/// the beam axis (the elastic axis) in their general form, with Peters' inflow states of the strip's own, act on
/// the node over the node's lumped length. A strip may carry a trailing-edge flap: the rotation of a node of
/// another beam (the control surface) relative to the strip's node about the pitch axis (A10); the flap's terms
/// join the lift and moment, and the hinge moment acts on the two nodes, equal and opposite. A strip on a rotor's
/// blade reads the rotor's induced inflow as a velocity of its air and adds its lift along the shaft to the
/// inflow's row (docs/theory.md, (A13)).

#include <string>

#include "flexmbd/aero/peters_inflow.hpp"
#include "flexmbd/aero/rotor_inflow.hpp"
#include "flexmbd/aero/thin_airfoil_loads.hpp"
#include "flexmbd/aero/typical_section_aero.hpp"
#include "flexmbd/elements/element.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

/// The flap of one strip: the control surface's node at the strip's span station.
struct StripFlap {
  int node = -1;          ///< the control surface's node (-1: no flap)
  int node_unknown = -1;  ///< its first unknown
  double fraction = 0.0;  ///< share of the strip's length the flap spans, 0 < fraction <= 1
  Mat3 R_rest = Mat3::Identity();  ///< the strip node's frame in the flap node's at rest: R_flap^T R_strip
};

/// The rotor whose blade carries a strip (docs/theory.md, (A13), (A14)).
struct StripRotor {
  int index = -1;             ///< the rotor's place in aero.rotors (-1: no rotor)
  int state = -1;             ///< the rotor's first inflow state in State::element_states
  int unknown = -1;           ///< its unknown; the other states' follow
  int num_states = 1;         ///< 1 (uniform nu) or 3 (nu_0, nu_c, nu_s)
  Vec3 axis = Vec3::UnitZ();  ///< the shaft axis in W; the inflow blows along -axis
  Vec3 center = Vec3::Zero();  ///< the disc's centre in W [m]
  /// (e_c, e_s) / R: the weights (r cos psi / R, r sin psi / R) of the harmonics per unit of the strip's place
  /// relative to the centre [1/m]
  Eigen::Matrix<double, 3, 2> harmonic_weights = Eigen::Matrix<double, 3, 2>::Zero();
};

class BeamStripAero : public Element {
 public:
  /// @param node the beam node; its unknowns start at node_unknown. @param length the strip's span [m].
  /// @param first_state_unknown the unknown of the strip's first inflow state. @param flap the flap, if any
  /// (spec.flap.c its hinge). @param rotor the rotor, if the strip is on a blade.
  BeamStripAero(const AeroStripSpec& spec, const AeroFlowSpec& flow, int node, int node_unknown, double length,
                int first_state_unknown, const StripFlap& flap = StripFlap(), const StripRotor& rotor = StripRotor());

  int num_states() const override { return inflow_.b.size(); }
  double StateScale(int) const override { return PetersStateScale(scale_); }
  std::string StateName(int k) const override { return "mu_" + std::to_string(k + 1); }
  std::string StateOwnerName() const override { return "aero strip " + name_; }

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  bool HasRateParts(AnalysisMode mode) const override { return mode != AnalysisMode::kStatic; }
  void AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                    Eigen::Ref<Eigen::MatrixXd> M) const override;
  /// The air's work on the node (and the flap's node) over a step: external work.
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;

  /// Lift [N] along the chord normal, moment [N m] nose up about the beam axis and hinge moment [N m] trailing
  /// edge down (zero without a flap), over the strip, at ctx.
  Vec3 StripLoads(const StepContext& ctx) const;
  /// The strip's span, the node's lumped length [m].
  double length() const { return length_; }
  /// The flap's deflection [rad] (trailing edge down) at ctx; zero without a flap.
  double FlapAngle(const StepContext& ctx) const;
  /// The strip's share of its rotor's rows at ctx: its lift along the axis T [N] times (1, r cos psi / R,
  /// r sin psi / R), the last two zero for a uniform inflow; all zero without a rotor.
  Eigen::Vector3d RotorRows(const StepContext& ctx) const;

 private:
  using States = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxInflowStates, 1>;
  // Rows of what the strip computes: lift, moment, hinge moment (per unit span), then the decay terms of the
  // inflow equations (u/b)(mu_i + lag_i w34).
  static constexpr int kMaxRows = 3 + kMaxInflowStates;
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxRows, 1>;
  using RowGradient = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMaxRows, 3>;
  // What the loads read at ctx: the section frame, the air's velocity relative to the node in it (V), the
  // node's angular velocity (w) and the rates of both (Vdot, wdot) in the section frame, the inflow states; with
  // a flap, the flap node's frame and angular velocity and rate (in its frame).
  struct Motion {
    Mat3 R, turn;  // section frame in W; its change per unit rotation increment
    Vec3 V, w, Vdot, wdot;
    Mat3 R_flap, turn_flap;
    Vec3 w_flap, wdot_flap;
    States mu, mu_rate;
    Vec3 v;  // the node's velocity in W
    // The rotor's states and their rates; the strip's weights of them (1, r cos psi / R, r sin psi / R); the
    // inflow at the strip and its rate along the strip's path; the gradients of both over the disc.
    RotorStates rotor_nu, rotor_nu_rate, weights;
    double nu = 0, nu_rate = 0;
    Vec3 nu_gradient = Vec3::Zero(), nu_rate_gradient = Vec3::Zero();
  };
  // The flap's deflection, its rate and acceleration, and the deflection's gradients by the rotation increments.
  struct Flap {
    Vec3 delta = Vec3::Zero();  // angle, rate, acceleration
    Eigen::Matrix<double, 1, 3> d_node = Eigen::Matrix<double, 1, 3>::Zero(), d_flap = d_node;
  };
  // The rows and their gradients with respect to V, w, Vdot, wdot (section frame), the flap's (angle, rate,
  // acceleration) and mu.
  struct Loads {
    double u = 0, w34 = 0;
    Eigen::Matrix<double, 1, 3> dw34_dV, dw34_dw, dw34_dflap;
    Rows y;
    RowGradient dV, dw, dVdot, dwdot, dflap;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRows, kMaxInflowStates> dmu;
  };
  Motion MotionAt(const StepContext& ctx) const;
  Flap FlapOf(const Motion& m) const;
  Loads Compute(const Motion& m, const Flap& f) const;
  // The lift, moment and hinge moment's (per unit span) flap terms (A10).
  void AddFlapTerms(const Motion& m, const Flap& f, Loads* out) const;
  // The map from (lift, moment, hinge) over the strip to the forces on the local node unknowns (rows).
  Eigen::Matrix<double, 12, 3> ForceMap(const Motion& m) const;
  int num_node_unknowns() const { return has_flap() ? 12 : 6; }
  bool has_flap() const { return flap_.node >= 0; }
  bool has_rotor() const { return rotor_.index >= 0; }
  // The local unknown (and row) of the rotor's first inflow state: after the strip's own states.
  int rotor_local() const { return num_node_unknowns() + num_states(); }
  // The weights' gradient by the strip's place (3 x rotor states): zero for nu_0, (e_c, e_s) / R for the harmonics.
  Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3> RotorWeightGradient() const;
  // The thrust per unit lift (per span): the strip's length times the chord normal's share along the axis.
  double ThrustShare(const Motion& m) const { return has_rotor() ? length_ * rotor_.axis.dot(m.R * normal_) : 0.0; }

  std::string name_;
  int node_;
  double semichord_, a_, length_, density_;
  Vec3 chord_, normal_, pitch_axis_;  ///< section frame; pitch_axis = normal x chord turns the nose up
  Vec3 free_stream_, gust_;
  TimeFunctionSpec gust_scale_;
  PetersInflow inflow_;
  Eigen::VectorXd lag_;  ///< Abar^-1 cbar: lambda - mu per unit w34
  double lag0_ = 0;      ///< bbar^T Abar^-1 cbar / 2: lambda0 - bbar^T mu / 2 per unit w34
  double scale_;         ///< speed of the free stream [m/s], the size of the states (PetersStateScale)
  StripFlap flap_;
  ThinAirfoilLoads flap_loads_;  ///< the section's generalised loads with the flap's hinge (A4), (A5)
  Vec3 flap_chord_, flap_pitch_axis_;  ///< chord and pitch axes in the flap node's frame
  StripRotor rotor_;
};

}  // namespace flexmbd
