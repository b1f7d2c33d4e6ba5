#pragma once
/// @file
/// A rotor's induced inflow (docs/theory.md, (A13), (A14)), the induced velocity through the disc along -axis.
/// Uniform: one state nu, lagging the momentum balance of the disc by the apparent mass of the air it moves,
///   m_a nu' + 2 rho A V_T nu = T,   m_a = (8/3) rho R^3,   A = pi R^2,   V_T = sqrt(V_p^2 + (V_c + nu)^2),
/// V_c the climb speed and V_p the in-plane speed of the stream through the disc. Harmonic: Pitt and Peters' three
/// states (nu_0, nu_c, nu_s), nu = nu_0 + (r/R)(nu_c cos psi + nu_s sin psi) over the disc, driven by the thrust and
/// the strips' moments (M_c, M_s) about the centre (A14). This element owns the states and adds the apparent mass and
/// momentum terms to their rows; each strip of the rotor's blades adds -(its lift along the axis) times
/// (1, r cos psi / R, r sin psi / R) to the same rows and reads nu at its place as a velocity of its air
/// (BeamStripAero, StripRotor).

#include <string>
#include <utility>
#include <vector>

#include "flexmbd/elements/element.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

class BeamStripAero;

/// A rotor's inflow states or their rates: at most three (A14), stored in place, so that evaluating them in the
/// Newton loop allocates nothing (issue 12).
using RotorStates = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;

class RotorInflow : public Element {
 public:
  /// @param first_state_unknown the unknown of the first inflow state (the others follow).
  RotorInflow(const AeroRotorSpec& spec, const AeroFlowSpec& flow, int first_state_unknown);

  int num_states() const override { return num_states_; }
  /// Induced velocities of rotors are metres per second (hover: sqrt(T / (2 rho A)), 5-15 m/s for disc loadings
  /// of 60-550 N/m^2; the harmonics a fraction of that); the error test's floor is error_tol / 1000 of this.
  double StateScale(int) const override { return 1.0; }
  std::string StateName(int k) const override { return k == 0 ? "nu" : (k == 1 ? "nu_c" : "nu_s"); }
  std::string StateOwnerName() const override { return "rotor " + name_; }

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  bool HasRateParts(AnalysisMode mode) const override { return mode != AnalysisMode::kStatic; }
  void AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                    Eigen::Ref<Eigen::MatrixXd> M) const override;

  const std::string& name() const { return name_; }
  bool harmonic() const { return harmonic_; }
  /// The blades' strips, whose lift drives the inflow (set once by the model builder; outputs read them).
  const std::vector<const BeamStripAero*>& strips() const { return strips_; }
  void set_strips(const std::vector<const BeamStripAero*>& strips) { strips_ = strips; }
  /// The rotor's loads at ctx: thrust, its strips' lift along the axis [N], and the moments of that lift about the
  /// centre, M_c = sum T_k r_k cos psi_k and M_s = sum T_k r_k sin psi_k [N m] (zero for the uniform inflow).
  Eigen::Vector3d Loads(const StepContext& ctx) const;
  double apparent_mass() const { return apparent_mass_; }  ///< m_a [kg]
  double disc_area() const { return disc_area_; }          ///< A [m^2]

 private:
  using StateSlope = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
  // The momentum terms of (A13) or (A14) and their derivative by the states, for the stream at time t.
  RotorStates Momentum(double t, const RotorStates& nu, StateSlope* slope) const;

  std::string name_;
  bool harmonic_;
  int num_states_;
  Vec3 axis_, center_;
  Vec3 e_c_, e_s_;  ///< the disc frame's in-plane axes in W: psi = 0 and psi = 90 deg, e_s = axis x e_c
  double radius_, density_, disc_area_, apparent_mass_;
  Vec3 free_stream_, gust_;
  TimeFunctionSpec gust_scale_;
  std::vector<const BeamStripAero*> strips_;
};

/// The number of inflow states of a rotor: 1 (uniform) or 3 (harmonic).
inline int RotorInflowStates(const AeroRotorSpec& spec) {
  return spec.inflow == AeroRotorSpec::Inflow::kHarmonic ? 3 : 1;
}

/// The in-plane axes (e_c, e_s) of a disc about `axis` (A14): e_c the world x axis projected on the disc (the y
/// axis when x is within 45 deg of the axis), e_s = axis x e_c.
std::pair<Vec3, Vec3> DiscAxes(const Vec3& axis);

}  // namespace flexmbd
