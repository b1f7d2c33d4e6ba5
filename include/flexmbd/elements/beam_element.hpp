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
/// (Gonzalez's discrete gradient), which keeps the energy identity (T6). Tangents are central finite
/// differences of the gradient.

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
  /// 6 * nodes[k]. @param length the element length [m].
  BeamElement(std::string name, std::vector<int> nodes, double length, const BeamSectionSpec& section);

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void AddEnergy(const State& state, const Vec3& gravity, EnergyTally* tally) const override;

  /// Section strains [eps; kappa] and forces [N; M] (section frame) at each Gauss point, for a state.
  struct SectionSample {
    double s = 0;  ///< position along the element from its first node [m]
    Eigen::Matrix<double, 6, 1> strain, load;
  };
  std::vector<SectionSample> SectionSamples(const State& state) const;

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
  Configuration AtState(const State& state) const;
  double Energy(const Configuration& c) const;
  // Gradient of V with respect to (dx_k, dtheta_k) applied at c as x_k + dx_k, R_k Exp(dtheta_k).
  Eigen::VectorXd Gradient(const Configuration& c) const;
  // The generalised forces of the context: gradient at the end (statics, end point) or the discrete
  // gradient of the step (dynamics).
  Eigen::VectorXd Forces(const StepContext& ctx, const std::vector<NodeStep>& nodes) const;

  std::string name_;
  std::vector<int> nodes_;
  std::shared_ptr<const Interpolation> interpolation_;
  double length_;
  Eigen::Matrix<double, 6, 6> stiffness_;
  int order_;
};

}  // namespace flexmbd
