#pragma once
/// @file
/// A rotor's uniform induced inflow (docs/theory.md, (A13)): one state nu, the induced velocity through the disc
/// along -axis, lagging the momentum balance of the disc by the apparent mass of the air it moves,
///   m_a nu' + 2 rho A V_T nu = T,   m_a = (8/3) rho R^3,   A = pi R^2,   V_T = sqrt(V_p^2 + (V_c + nu)^2),
/// V_c the climb speed and V_p the in-plane speed of the stream through the disc. This element owns the state and
/// adds m_a nu' + 2 rho A V_T nu to its row; each strip of the rotor's blades adds -(its lift along the axis) to the
/// same row and reads nu as a velocity of its air (BeamStripAero, StripRotor).

#include <string>
#include <vector>

#include "flexmbd/elements/element.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

class BeamStripAero;

class RotorInflow : public Element {
 public:
  /// @param state_unknown the unknown of the inflow state.
  RotorInflow(const AeroRotorSpec& spec, const AeroFlowSpec& flow, int state_unknown);

  int num_states() const override { return 1; }
  /// Induced velocities of rotors are metres per second (hover: sqrt(T / (2 rho A)), 5-15 m/s for disc loadings
  /// of 60-550 N/m^2); the error test's floor is error_tol / 1000 of this.
  double StateScale(int) const override { return 1.0; }
  std::string StateName(int) const override { return "nu"; }
  std::string StateOwnerName() const override { return "rotor " + name_; }

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  bool HasRateParts(AnalysisMode mode) const override { return mode != AnalysisMode::kStatic; }
  void AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D, Eigen::Ref<Eigen::MatrixXd> M) const override;

  const std::string& name() const { return name_; }
  /// The blades' strips, whose lift drives the inflow (set once by the model builder; outputs read them).
  const std::vector<const BeamStripAero*>& strips() const { return strips_; }
  void set_strips(const std::vector<const BeamStripAero*>& strips) { strips_ = strips; }
  /// The rotor's thrust at ctx: its strips' lift along the axis [N].
  double Thrust(const StepContext& ctx) const;
  double apparent_mass() const { return apparent_mass_; }  ///< m_a [kg]
  double disc_area() const { return disc_area_; }          ///< A [m^2]

 private:
  // The momentum term 2 rho A V_T nu of (A13) and its derivative by nu, for the stream at time t.
  double Momentum(double t, double nu, double* slope) const;

  std::string name_;
  Vec3 axis_;
  double density_, disc_area_, apparent_mass_;
  Vec3 free_stream_, gust_;
  TimeFunctionSpec gust_scale_;
  std::vector<const BeamStripAero*> strips_;
};

}  // namespace flexmbd
