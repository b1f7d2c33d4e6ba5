#pragma once
/// @file
/// The one element interface (DESIGN.md): bodies, joints, effects and loads all declare the unknowns they
/// couple, add their residual and their tangent. The same code serves static and dynamic analyses; the
/// StepContext says which. The tangent comes in parts (DESIGN.md): the stiffness part at held end rates, and the
/// derivatives with respect to end rates and accelerations, which each scheme combines with its own
/// coefficients (AddSchemeRateTerms) and eigen-analysis takes as they are (damping and mass matrices).
///
/// Unknowns of a step (docs/theory.md, "Unknowns"): per node the increment (dx in W, theta in the node frame at
/// the start of the step, R_f = R_i Exp(theta)); per joint variable its increment dq; the multipliers lambda.
/// Residual rows of node and variable unknowns are generalised forces conjugate to those increments.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "flexmbd/elements/element_workspace.hpp"
#include "flexmbd/math/so3.hpp"
#include "flexmbd/model/state.hpp"

namespace flexmbd {

using Vec6 = Eigen::Matrix<double, 6, 1>;

/// Which analysis is asking.
enum class AnalysisMode {
  kDynamic,   ///< a time step from state i to state f with mid-step (discrete-gradient) forces
  kStatic,    ///< equilibrium at the current iterate: start and end coincide (theta = 0)
  kEndPoint,  ///< a time step whose equations hold at its end (generalized-alpha): forces at the current
              ///< end iterate as in kStatic, inertia and damping from the end velocities and accelerations
};

/// Integration coefficients of the dynamic scheme for one node (docs/theory.md, eq. (T3)):
///   x_f - x_i = h [(v_i + v_f)/2 + alpha (v_f - v_i - h a_prev)],
/// a_prev the mean acceleration of the previous step; the same for theta, w and the angular acceleration.
struct NodeSchemeCoefficients {
  double alpha_translation = 0.0;  ///< >= 0; 0 is energy preserving
  double alpha_rotation = 0.0;     ///< >= 0
};

/// A node's start and trial-end configuration and velocities for one evaluation.
struct NodeStep {
  Vec3 x_i, x_f, dx;
  Mat3 R_i, R_f;
  Vec3 theta;          ///< rotation increment, node frame at i
  Mat3 S;              ///< SecantOperator(theta)
  Mat3 T;              ///< RightJacobian(theta)
  Vec3 v_i, v_f, w_i, w_f;
  Vec3 vdot_f = Vec3::Zero(), wdot_f = Vec3::Zero();  ///< end accelerations (kEndPoint only)
  /// The scheme's coefficients, which combine an element's rate parts into its tangent (AddSchemeRateTerms);
  /// elements do not read them.
  double dvf_ddx = 0;     ///< d v_f / d dx (scalar times identity)
  double dwf_dtheta = 0;  ///< d w_f / d theta
  double dacc = 0;        ///< d vdot_f / d dx = d wdot_f / d theta (kEndPoint only)
};

/// Builds the configuration part of a NodeStep from the start state and the increment (dx, theta). In the
/// modes that evaluate at the end (kStatic, kEndPoint) the start is moved to the end: the node stands at
/// start + increment with theta = 0.
NodeStep MakeNodeStep(const NodeState& start, const Vec6& increment, AnalysisMode mode);

/// Fills the velocity part of a dynamic NodeStep from the scheme relation (theory eq. (T3)); uses the start
/// state's velocities and previous-step accelerations.
void SetNodeStepVelocities(const NodeState& start, double h, const NodeSchemeCoefficients& c, NodeStep* node);

/// The configuration of `node` moved by a further increment d as the solver moves it (velocities are left
/// unset): what the tests difference to check analytic tangents.
NodeStep PerturbNodeStep(const NodeStep& node, const Vec6& d, AnalysisMode mode);

/// One joint variable's start and trial-end values.
struct VariableStep {
  double q_i = 0, q_f = 0, qdot_i = 0;
  double alpha = 0;      ///< dissipation coefficient of the energy-decaying scheme for springs on q (>= 0)
  double dq_lagged = 0;  ///< the previous step's increment scaled to this step, (h / h_prev) dq_prev
  double qdot_f = 0;     ///< end rate (kEndPoint only)
  double dqdotf_dq = 0;  ///< the scheme's d qdot_f / d dq (kEndPoint only; AddSchemeRateTerms)
};

/// One element state's start and trial-end values, and the value and rate its equations are evaluated at
/// (docs/theory.md, "Element states", (S1)-(S3)).
struct ElementStateStep {
  double x_i = 0, x_f = 0;  ///< start and trial-end value
  double value = 0;         ///< where the element's equations read the state: mid-step, or the end
  double rate = 0;          ///< the state's rate there: (x_f - x_i)/h mid-step, 0 static, the scheme's end rate
  double drate = 0;         ///< d rate / d increment of the scheme (AddSchemeRateTerms); d value / d increment is
                            ///< StepContext::mid_rate()
};

/// What an element may read during one evaluation.
struct StepContext {
  AnalysisMode mode = AnalysisMode::kDynamic;
  double t_i = 0, t_f = 0, h = 1;    ///< step start, end and size [s]
  double load_factor = 1;            ///< static load stepping: multiplies gravity and applied loads
  Vec3 gravity = Vec3::Zero();       ///< [m/s^2]
  const State* start = nullptr;
  const std::vector<NodeStep>* nodes = nullptr;
  const std::vector<VariableStep>* variables = nullptr;
  const Eigen::VectorXd* lambda = nullptr;  ///< trial multipliers (num_multipliers)
  const std::vector<EffectState>* effects = nullptr;  ///< trial modes of the effects with modes
  const std::vector<ElementStateStep>* element_states = nullptr;  ///< every element's own states (Model order)
  /// Add the stress-dependent (geometric) terms to the tangent: the second derivatives of constraint forces and
  /// loads, and in a dynamic step the geometric stiffness of beam section forces.
  bool geometric_stiffness = false;
  /// Energy-decaying coefficient alpha of each element's own stretch, by Element::index() (null: none).
  const std::vector<double>* element_alpha = nullptr;
  /// The elements' workspaces for their caches (null: elements compute everything afresh).
  ElementWorkspaces* workspaces = nullptr;
  /// Per joint variable, the rate a drive follows from the step's start instead of its law or set-point, q_f = q_i + h
  /// rate (null: its law or set-point): the short steps of a velocity projection at a jump of a drive's rate.
  const Eigen::VectorXd* drive_rates = nullptr;
  /// True when forces are evaluated at the end configuration (start moved to the end, theta = 0).
  bool at_end() const { return mode != AnalysisMode::kDynamic; }
  /// d(mid-step value)/d(increment): 1/2 with mid-step forces, 1 at the end configuration.
  double mid_rate() const { return at_end() ? 1.0 : 0.5; }
  /// The time forces are evaluated at: the step's end, or its middle for mid-step forces.
  double force_time() const { return at_end() ? t_f : 0.5 * (t_i + t_f); }
};

/// Energy terms of one element at one state.
struct EnergyTally {
  double kinetic = 0;    ///< [J]
  double potential = 0;  ///< gravity and springs [J]
};

/// Work done over one accepted step.
struct StepWork {
  double external = 0;    ///< by applied loads, drives and commanded efforts [J]
  double dissipated = 0;  ///< by dampers, friction, contact and structural damping (>= 0) [J]
  /// By the integrator's dissipation in elastic elements (>= 0), and the scheme's share of a frictional step's work,
  /// where the friction's would be negative (<= 0, docs/theory.md (F9)) [J].
  double numerical = 0;
};

/// Most local unknowns an element with rate parts may have: a cubic beam's 4 nodes.
constexpr int kMaxRatePartUnknowns = 24;

/// Base of every element. Local unknowns are a list of global indices fixed at model build.
class Element {
 public:
  virtual ~Element() = default;

  /// Global indices of the local unknowns, in local order.
  const std::vector<int>& unknowns() const { return unknowns_; }
  int num_local() const { return static_cast<int>(unknowns_.size()); }

  /// Adds the local residual r (size num_local) and, per row, the magnitude of the terms added (for
  /// scale-free convergence tests).
  virtual void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                           Eigen::Ref<Eigen::VectorXd> magnitude) const = 0;

  /// Adds the stiffness part of the local tangent (num_local x num_local): dr/d(unknowns) with the end rates and
  /// accelerations of the nodes and joint variables held. Elements whose residual reads those rates give their
  /// derivatives apart (AddRateParts); the scheme combines the parts with its own coefficients (AddSchemeTangent).
  virtual void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const = 0;

  /// True when the residual in this mode reads end rates or accelerations (NodeStep v_f, w_f, vdot_f, wdot_f;
  /// VariableStep qdot_f), so that AddRateParts adds something.
  virtual bool HasRateParts(AnalysisMode /*mode*/) const { return false; }

  /// Adds the rate parts of the local tangent: D = dr/d(end rates) and M = dr/d(end accelerations), both
  /// num_local x num_local, columns in local order (node translation rates v_f, body-frame rotation rates w_f,
  /// joint variable rates qdot_f, element state rates; multiplier columns stay zero). Only called when
  /// HasRateParts(ctx.mode).
  virtual void AddRateParts(const StepContext& /*ctx*/, Eigen::Ref<Eigen::MatrixXd> /*D*/,
                            Eigen::Ref<Eigen::MatrixXd> /*M*/) const {}

  /// Both at once, for elements that share work between them; J may be null (residual only). The default
  /// calls AddResidual and AddTangent.
  virtual void AddResidualAndTangent(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                                     Eigen::Ref<Eigen::VectorXd> magnitude, Eigen::Ref<Eigen::MatrixXd>* J) const {
    AddResidual(ctx, r, magnitude);
    if (J != nullptr) AddTangent(ctx, *J);
  }

  /// Energy stored at a state (zero by default).
  virtual void AddEnergy(const State&, const Vec3& /*gravity*/, EnergyTally*) const {}

  /// Work done by the element over the converged step described by ctx (zero by default).
  virtual void AddStepWork(const StepContext&, StepWork*) const {}

  /// Size of the element's own history in State::element_history (0: it keeps none).
  virtual int history_size() const { return 0; }
  /// Writes the element's history after the accepted step ctx (only called when history_size() > 0).
  virtual void RecordHistory(const StepContext& /*ctx*/, Eigen::VectorXd* /*history*/) const {}

  /// Number of first-order states the element owns (DESIGN.md "Elements may own states"): unknowns of their own
  /// whose rows are the element's first-order equations F(rate, value, ...) = 0 (docs/theory.md, (S1)).
  virtual int num_states() const { return 0; }
  /// The size at which the element's state k is measured [its units]: the local error test's floor is
  /// error_tol / 1000 of it (docs/theory.md, (T12)).
  virtual double StateScale(int /*k*/) const { return 1.0; }
  /// Name of state k in messages and outputs, e.g. "lambda_0".
  virtual std::string StateName(int k) const { return "state " + std::to_string(k); }
  /// Name of the element in messages about its states.
  virtual std::string StateOwnerName() const { return "element " + std::to_string(index_); }
  /// Index of the element's first state in State::element_states (set by the model builder; -1: none).
  int first_state() const { return first_state_; }
  void set_first_state(int first) { first_state_ = first; }

  /// A workspace of the element's own for caches (element_workspace.hpp); null: it keeps none.
  virtual std::unique_ptr<ElementWorkspace> MakeWorkspace() const { return nullptr; }

  /// Position in Model::elements(), which indexes State::element_history and StepContext::element_alpha.
  int index() const { return index_; }
  /// Set once by the model builder.
  void set_index(int index) { index_ = index; }

 protected:
  /// The scheme's dissipation coefficient for this element's stretch in ctx (0 outside energy-decaying steps).
  double Alpha(const StepContext& ctx) const {
    return ctx.element_alpha != nullptr && ctx.mode == AnalysisMode::kDynamic ? (*ctx.element_alpha)[index_] : 0.0;
  }

  /// The element's workspace in ctx as made by MakeWorkspace (null when ctx carries none).
  template <class Workspace>
  Workspace* WorkspaceIn(const StepContext& ctx) const {
    return ctx.workspaces != nullptr ? static_cast<Workspace*>(ctx.workspaces->of(index_)) : nullptr;
  }

  std::vector<int> unknowns_;

 private:
  int index_ = -1;
  int first_state_ = -1;
};

/// Adds to J the rate parts of an element combined with the scheme's coefficients of ctx, column by column:
/// D diag(d rate / d increment) + M diag(d acceleration / d increment), the coefficients being NodeStep::dvf_ddx,
/// dwf_dtheta and dacc of the column's node and VariableStep::dqdotf_dq of its variable. With the stiffness part
/// (Element::AddTangent) this makes the tangent of the scheme's equations. No heap allocation.
void AddSchemeRateTerms(const Element& element, const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J);

/// The element's whole tangent for ctx added to J: AddTangent and AddSchemeRateTerms.
void AddSchemeTangent(const Element& element, const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J);

}  // namespace flexmbd
