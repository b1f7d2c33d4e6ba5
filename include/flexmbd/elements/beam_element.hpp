#pragma once
/// @file
/// Geometrically exact, shear-deformable beam element (Simo-Reissner; docs/theory.md, "Beams", (B1)-(B5)).
/// Nodes carry a position and a rotation whose x axis is the beam axis in the reference (straight, untwisted)
/// configuration. Positions are interpolated with Lagrange polynomials of order 1 to 3; rotations relative to
/// the middle node, R(s) = R_r Exp(sum_k N_k(s) Log(R_r^T R_k)), which is objective. Strains in the section
/// frame: eps = R^T x' - e1, kappa = T(psi) psi'. Strain energy V = 1/2 int [eps; kappa]^T C [eps; kappa] ds,
/// integrated with order Gauss points (reduced, free of shear locking).
///
/// Generalised forces are the exact gradient of V (forward-mode automatic differentiation). In a dynamic step
/// they are the gradient at the mid-step configuration corrected so that G . increments = V_f - V_i exactly
/// (Gonzalez's discrete gradient), which keeps the energy identity (T6). Structural damping adds the viscous
/// section forces mu C eps_dot (B7); over a step they dissipate exactly mu sum_g w_g deps^T C deps / h.
/// Tangents are central finite differences of the forces.

#include <memory>
#include <string>
#include <vector>

#include "flexmbd/elements/element.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

class BeamElement : public Element {
 public:
  static constexpr int kMaxNodes = 4;

  /// @param nodes the element's node indices along the beam (order + 1 of them); node k's unknowns start at
  /// 6 * nodes[k]. @param length the element length [m]. @param stiffness the 6x6 section stiffness C about
  /// the beam axis (offsets already applied, BeamSectionStiffness). @param damping mu >= 0 [s] (B7).
  BeamElement(std::string name, std::vector<int> nodes, double length, const Eigen::Matrix<double, 6, 6>& stiffness,
              double damping);

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void AddEnergy(const State& state, const Vec3& gravity, EnergyTally* tally) const override;
  /// Energy dissipated by structural damping over the step (B7).
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;

  /// One section of the element at a state, interpolated with the shape functions (B1)-(B2).
  struct Section {
    Eigen::Matrix<double, 6, 1> strain;  ///< [eps; kappa], section frame [-, 1/m]
    Eigen::Matrix<double, 6, 1> load;    ///< [N; M] = C (strain + mu strain rate), section frame [N, N m]
    Vec3 x = Vec3::Zero();               ///< position of the beam axis [m]
    Mat3 R = Mat3::Identity();           ///< section frame in W
  };
  /// The section at distance s from the element's first node, 0 <= s <= length [m]; the strain rate of the
  /// damping part comes from the state's node velocities.
  Section SectionAt(const State& state, double s) const;

  const std::string& name() const { return name_; }
  const std::vector<int>& nodes() const { return nodes_; }

  struct Interpolation;  ///< shape functions at the Gauss points (defined with the element's code)

 private:
  using Vec6 = Eigen::Matrix<double, 6, 1>;
  // Node configurations the energy is evaluated about (positions and rotations per node).
  struct Configuration {
    std::vector<Vec3> x;
    std::vector<Mat3> R;
  };
  // Section strains at the Gauss points and their derivatives with respect to (dx_k, dtheta_k) applied at c
  // as x_k + dx_k, R_k Exp(dtheta_k).
  struct Linearisation {
    std::vector<Vec6> strain;
    std::vector<Eigen::MatrixXd> B;  // 6 x 6(order + 1) per Gauss point
  };
  Configuration AtState(const State& state) const;
  std::vector<Vec6> GaussStrains(const Configuration& c) const;
  double Energy(const std::vector<Vec6>& strains) const;
  Linearisation Linearise(const Configuration& c) const;
  // sum_g w_g B_g^T stress_g: the generalised forces of section forces given at the Gauss points.
  Eigen::VectorXd NodalForces(const Linearisation& lin, const std::vector<Vec6>& stress) const;
  // The generalised forces of the context: gradient at the end (statics, end point) or the discrete
  // gradient of the step (dynamics), plus damping in the dynamic modes.
  Eigen::VectorXd Forces(const StepContext& ctx, const std::vector<NodeStep>& nodes) const;
  // The dynamic step's damping forces (B7) from the mid-step linearisation.
  Eigen::VectorXd StepDampingForces(const StepContext& ctx, const Linearisation& mid, const std::vector<Vec6>& strain_i,
                                    const std::vector<Vec6>& strain_f, const Eigen::VectorXd& increments,
                                    const Eigen::VectorXd& weighted, double strain_round_off) const;
  // Round-off of a strain computed from these node positions: eps times the largest coordinate over the
  // element length [-].
  double StrainRoundOff(const std::vector<NodeStep>& steps) const;

  std::string name_;
  std::vector<int> nodes_;
  std::shared_ptr<const Interpolation> interpolation_;
  double length_;
  Eigen::Matrix<double, 6, 6> stiffness_;
  double damping_;  ///< mu [s]
  int order_;
};

}  // namespace flexmbd
