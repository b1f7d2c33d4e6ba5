#pragma once
/// @file
/// The aerodynamic element of a typical section (docs/theory.md, (A6)): the generalised thin-airfoil loads of
/// ThinAirfoilLoads on the plunge, pitch and flap joint variables, and Peters' inflow states as states of its
/// own, in the variables mu = lambda - Abar^-1 cbar (w0 + w1/2) that no acceleration drives (A6). Positions come
/// from the joint variables; rates and accelerations from the velocities of the three bodies'
/// nodes (the scheme's own, so that the apparent-mass terms act as inertia does in each scheme).

#include <string>

#include "flexmbd/aero/peters_inflow.hpp"
#include "flexmbd/aero/thin_airfoil_loads.hpp"
#include "flexmbd/elements/element.hpp"

namespace flexmbd {

/// Most inflow states a section takes (Peters' eight reproduce C(k) within 1% up to k = 1).
constexpr int kMaxInflowStates = 10;

class TypicalSectionAero : public Element {
 public:
  /// One generalised coordinate q_k = sign * (joint variable), its rate read from node velocities:
  /// q_k' = rate^T (v_P, w_A, w_F) over the plunge body's translation and the pitch and flap bodies' rotations.
  struct Coordinate {
    int variable = -1, variable_unknown = -1;
    double sign = 1.0;
    Eigen::Matrix<double, 9, 1> rate = Eigen::Matrix<double, 9, 1>::Zero();
  };
  /// `node_unknowns`: first unknowns of the plunge, pitch and flap bodies' nodes.
  TypicalSectionAero(const AeroSectionSpec& spec, const int node_unknowns[3], const Coordinate coordinates[3],
                     int first_state_unknown);

  int num_states() const override { return inflow_.b.size(); }
  double StateScale(int) const override { return PetersStateScale(velocity_); }
  std::string StateName(int k) const override { return "mu_" + std::to_string(k + 1); }
  std::string StateOwnerName() const override { return "aero section " + name_; }
  const std::string& name() const { return name_; }

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  bool HasRateParts(AnalysisMode mode) const override { return mode != AnalysisMode::kStatic; }
  void AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                    Eigen::Ref<Eigen::MatrixXd> M) const override;
  /// The air's work on the section over a step: external work.
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;

  /// Section loads at ctx: lift [N] (up), moment about the elastic axis [N m] (nose up), hinge moment [N m]
  /// (trailing edge down), all over the span.
  Vec3 SectionLoads(const StepContext& ctx) const;

 private:
  // The motion the loads read at ctx: positions, rates, accelerations of (h, alpha, delta), inflow and its rate.
  struct Motion {
    Vec3 q, qd, qdd;
    Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxInflowStates, 1> lambda, lambda_rate;
  };
  Motion Evaluate(const StepContext& ctx) const;
  // lambda0 = bbar^T lambda / 2 with lambda = mu + Abar^-1 cbar ew^T q' (A6).
  double Lambda0(const Motion& m) const;
  // The forces on (h, alpha, delta) over the span (A4), h positive down.
  Vec3 GeneralisedForces(const Motion& m) const;
  // d(rate)/d(end node rate) and d(acceleration)/d(end node rate) of the scheme in ctx's mode.
  void RateFactors(const StepContext& ctx, double* rate, double* acceleration) const;

  std::string name_;
  ThinAirfoilLoads loads_;
  PetersInflow inflow_;
  double velocity_, density_, span_;
  Coordinate coordinates_[3];
  Eigen::Matrix<double, 3, 9> rates_;  ///< rows: the coordinates' rate weights
  Eigen::VectorXd lag_;                ///< Abar^-1 cbar: lambda - mu per unit ew^T q'
  double lag0_ = 0;                    ///< bbar^T Abar^-1 cbar / 2: lambda0 - bbar^T mu / 2 per unit ew^T q'

};

}  // namespace flexmbd
