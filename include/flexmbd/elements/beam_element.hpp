#pragma once
/// @file
/// Geometrically exact, shear-deformable beam element (Simo-Reissner; docs/theory.md, "Beams", (B1)-(B12)).
/// Nodes carry a position and a rotation whose x axis is the beam axis in the reference (straight, untwisted)
/// configuration. Positions are interpolated with Lagrange polynomials of order 1 to 3; rotations relative to
/// the middle node, R(s) = R_r Exp(sum_k N_k(s) Log(R_r^T R_k)), which is objective. Strains in the section
/// frame: eps = R^T x' - e1, kappa = T(psi) psi'. Strain energy V = 1/2 int [eps; kappa]^T C [eps; kappa] ds,
/// integrated with order Gauss points (reduced, free of shear locking).
///
/// Generalised forces are the exact gradient of V and tangents their exact derivatives, both analytic
/// (BeamStrainField). In a dynamic step the section forces are C times the mean of the end strains, paired with
/// the strain Jacobian of the mid-step configuration corrected so that it maps the increments onto the strain
/// changes exactly: G . increments = V_f - V_i, which keeps the energy identity (T6) (B5). Structural damping
/// adds the viscous section forces mu C eps_dot (B7); over a step they dissipate exactly
/// mu sum_g w_g deps^T C deps / h.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "flexmbd/elements/beam_shape.hpp"
#include "flexmbd/elements/beam_strain_field.hpp"
#include "flexmbd/elements/element.hpp"

namespace flexmbd {

class BeamElement : public Element {
 public:
  /// @param nodes the element's node indices along the beam (order + 1 of them); node k's unknowns start at
  /// 6 * nodes[k]. @param length the element length [m]. @param stiffness the 6x6 section stiffness C about
  /// the beam axis (offsets already applied, BeamSectionStiffness). @param damping mu >= 0 [s] (B7).
  BeamElement(std::string name, std::vector<int> nodes, double length, const Eigen::Matrix<double, 6, 6>& stiffness,
              double damping);

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override;
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void AddResidualAndTangent(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                             Eigen::Ref<Eigen::VectorXd> magnitude, Eigen::Ref<Eigen::MatrixXd>* J) const override;
  /// Structural damping at the end point (generalized-alpha, eigen-analysis) reads the end rates (B7).
  bool HasRateParts(AnalysisMode mode) const override;
  void AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                    Eigen::Ref<Eigen::MatrixXd> M) const override;
  void AddEnergy(const State& state, const Vec3& gravity, EnergyTally* tally) const override;
  /// Energy dissipated over the step by structural damping (B7) and by the scheme on the strains (B13).
  void AddStepWork(const StepContext& ctx, StepWork* work) const override;
  /// The strain change of the last accepted step at each Gauss point, for the scheme's dissipation (B13).
  int history_size() const override { return 6 * shape_.num_points; }
  void RecordHistory(const StepContext& ctx, Eigen::VectorXd* history) const override;
  /// Keeps the strains of a step's start and of its last end configuration (StrainMemo).
  std::unique_ptr<ElementWorkspace> MakeWorkspace() const override;

  /// One section of the element at a state, interpolated with the shape functions (B1)-(B2).
  struct Section {
    Eigen::Matrix<double, 6, 1> strain;  ///< [eps; kappa], section frame [-, 1/m]
    Eigen::Matrix<double, 6, 1> load;    ///< [N; M] = C strain, the elastic part, section frame [N, N m]
    Vec3 x = Vec3::Zero();               ///< position of the beam axis [m]
    Vec3 v = Vec3::Zero();               ///< its velocity, sum_k N_k v_k, in W [m/s]
    Mat3 R = Mat3::Identity();           ///< section frame in W
  };
  /// The section at distance s from the element's first node, 0 <= s <= length [m].
  Section SectionAt(const State& state, double s) const;
  /// The structural damping part mu C eps_dot (B7) of the section forces at s that the step `step` applied,
  /// section frame [N, N m]: in a dynamic step the rate of the strains over it, (eps_f - eps_i) / h, which a
  /// rigid motion leaves at zero; at the end point B (v_f, w_f); none in statics (docs/theory.md, "Station
  /// outputs").
  Eigen::Matrix<double, 6, 1> DampingLoadAt(const StepContext& step, double s) const;

  const std::string& name() const { return name_; }
  const std::vector<int>& nodes() const { return nodes_; }

 private:
  using Field = BeamStrainField;
  using Mat6 = Eigen::Matrix<double, 6, 6>;

  // The element's generalised forces for the context, added to forces, and their derivative with respect to
  // the element's unknowns, added to K when K is not null.
  void Evaluate(const StepContext& ctx, Field::Vector* forces, Field::Matrix* K) const;
  // The end configuration of the element's nodes and their end rates (v, w) in local order.
  void EndNodesAndRates(const StepContext& ctx, Field::Nodes* end, Field::Vector* rates) const;
  // Statics and the end point: the gradient at the end configuration, plus damping at the end point.
  void EvaluateAtEnd(const StepContext& ctx, Field::Vector* forces, Field::Matrix* K) const;
  // The dynamic step: the discrete gradient (B5) and the step's damping forces (B7), (B13).
  void EvaluateStep(const StepContext& ctx, Field::Vector* forces, Field::Matrix* K) const;
  struct StepFields;
  // The step's section forces, elastic (B5), structural damping (B7) and the scheme's (B13), and what their
  // tangent reuses.
  struct StepStress {
    Field::Vector forces;
    // w C [(e_i + e_f)/2 + (mu/h + alpha) de - alpha de_lagged] and de - B_mid d per point
    Field::PointVectors stress, gap;
    std::array<Mat6, BeamShape::kMaxPoints> rate;  // d stress / d e_f
    double gap_work = 0;  // sum_g gap . stress
  };
  StepStress StepStresses(const StepContext& ctx, const StepFields& step) const;
  // The derivative of the gap term of (B5); K_mid is the geometric tangent of the stresses at the middle
  // configuration, in the step's increments.
  void AddGapTangent(const StepFields& step, const StepStress& stress, const Field::Vector& K_mid_transposed_d,
                     Field::Matrix* K) const;
  // K += d/dd [value W d / (d^T W d)] given d value / dd: the gap correction of (B5).
  void AddCorrectionDerivative(const StepFields& step, double value, const Field::Vector& derivative,
                               Field::Matrix* K) const;

  // The element's workspace: the strains of the configurations it was last asked about at a step's start and
  // end, which every evaluation of a step shares (the start) and its work and history read again (the end).
  struct StrainMemo;
  struct KeptStrains;
  // The strains (Order kStrains) at nodes: those kept, when kept for these very nodes, else computed and kept in
  // `kept` (if not null).
  Field::PointVectors StrainsAt(const Field::Nodes& nodes, KeptStrains* kept) const;

  Field::Nodes AtState(const State& state) const;
  // The weights that carry values at the Gauss points to s by the polynomial through them ("Station outputs").
  std::array<double, BeamShape::kMaxPoints> StationWeights(double s) const;
  // The element's nodes at the start and the end of the step of ctx.
  void StepEnds(const StepContext& ctx, Field::Nodes* start, Field::Nodes* end) const;
  double Energy(const Field& field) const;
  // The strain changes of the step at the Gauss points, and the previous step's scaled to this step's size.
  Field::PointVectors StrainChanges(const StepContext& ctx) const;
  Vec6 LaggedStrainChange(const StepContext& ctx, int point) const;
  // Round-off of a strain computed from these node positions: eps times the largest coordinate over the
  // element length [-].
  double StrainRoundOff(const StepContext& ctx) const;

  std::string name_;
  std::vector<int> nodes_;
  double length_;
  Mat6 stiffness_;
  double damping_;  ///< mu [s]
  BeamShape shape_;
  std::array<Mat6, BeamShape::kMaxPoints> weighted_stiffness_;  ///< w_g C
};

}  // namespace flexmbd
