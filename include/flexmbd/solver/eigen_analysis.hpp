#pragma once
/// @file
/// Linearised eigen-analysis about a state (docs/theory.md, "Eigen-analysis", eqs. (E1)-(E6)): the
/// end-point tangent of every element gives the stiffness K, velocity (damping and gyroscopic) D and mass M
/// matrices over the node and joint-variable unknowns, and the constraint Jacobian B; the constraints are
/// removed with a basis Z of the null space of B, and the first-order form of the reduced problem is solved
/// for natural frequencies, damping ratios and mode shapes. A sweep of one parameter gives a fan-plot table.
///
/// @code
///   const Model model = BuildModel(spec);
///   State state = model.initial_state();           // or the equilibrium from SolveStatic
///   const EigenResult result = EigenAnalysis(model, state, EigenOptions{});
///   std::puts(FormatModeTable(result).c_str());
/// @endcode

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "flexmbd/model/model.hpp"
#include "flexmbd/model/state.hpp"

namespace flexmbd {

/// How the accelerations and multipliers of the state to linearise about are obtained (theory (E2)).
enum class ReferenceMotion {
  kConsistent,        ///< solved from the equations of motion at the state's positions and velocities (default):
                      ///< exact for a static equilibrium and for steady motion, and needs no multipliers
  kFromState,         ///< as stored: a_prev, alpha_prev, qddot_prev and lambda (the last step's values)
  kZeroAcceleration,  ///< zero accelerations, the stored multipliers
};

/// How the eigenproblem is solved.
enum class EigenMethod {
  kAuto,    ///< dense up to EigenOptions::dense_limit kinematic unknowns, sparse shift-invert above
  kDense,   ///< null-space elimination and a dense eigensolver: every mode
  kSparse,  ///< shift-invert Arnoldi on the constrained quadratic pencil, factorised by KLU: the lowest modes
};

/// Settings of one eigen-analysis.
struct EigenOptions {
  int num_modes = 0;  ///< modes reported, lowest frequency first; 0 reports all (dense) or 10 (sparse)
  ReferenceMotion reference = ReferenceMotion::kConsistent;
  EigenMethod method = EigenMethod::kAuto;
  int dense_limit = 2000;           ///< kAuto: largest number of kinematic unknowns solved densely
  double shift_hz = 0.0;            ///< sparse: frequency near which modes are sought [Hz]; 0 = the lowest
  double rigid_tolerance = 1.0e-8;  ///< dense: |s| below this times the model's frequency scale (about its highest
                                    ///< frequency) is a rigid-body mode (and see theory (E5)); the sparse method
                                    ///< judges zero roots against its shift (E6)
};

/// One mode of the linearised system: motion x(t) = Re(shape e^{s t}).
struct Mode {
  std::complex<double> eigenvalue;   ///< s = -zeta omega_n + i omega_d [1/s]; 0 for a rigid-body mode
  double frequency_hz = 0.0;         ///< undamped natural frequency |s| / 2 pi [Hz]
  double damped_frequency_hz = 0.0;  ///< |Im s| / 2 pi [Hz]
  double damping_ratio = 0.0;        ///< -Re s / |s|: 0 undamped, 1 for a real (overdamped) root, < 0 unstable
  bool rigid_body = false;           ///< a zero-frequency motion (free joint, free body)
  double growth_round_off = 0.0;     ///< the eigen-solver's round-off in Re s of this root [1/s]: growth up to it is
                                     ///< no instability (theory (E5))
  Eigen::VectorXcd shape;            ///< over the node and variable unknowns (6 num_nodes + num_variables) [m, rad],
                                     ///< scaled so that its largest component is 1
};

/// Result of one eigen-analysis.
struct EigenResult {
  std::vector<Mode> modes;  ///< rigid-body modes first, then by increasing frequency_hz
  int num_kinematic = 0;    ///< node and variable unknowns
  int num_dof = 0;          ///< degrees of freedom left after removing the independent constraints
  int num_rigid_body = 0;   ///< rigid-body modes among all (dense) or among those found (sparse)
  int num_states = 0;       ///< element states among the num_kinematic, the last entries of each shape (theory (E7))
  /// The largest root's |s| / 2 pi, against which round-off is judged (theory (E5)) [Hz].
  double frequency_scale_hz = 0.0;
  bool symmetric = false;   ///< solved as an undamped symmetric problem (no damping, no gyroscopic terms)
  std::string method;       ///< "dense" or "sparse shift-invert"
};

/// The linearised equations M y'' + D y' + K y + B^T mu = 0, B y = 0 (theory eqs. (E1), (E3)) in the
/// perturbation coordinates y: per node its translation and rotation in the node frame (so that a steadily
/// rotating system has constant coefficients), joint variables as they are. The kinematic unknowns (dx in W,
/// theta, dq) are x = T y.
struct LinearisedSystem {
  State reference;                ///< the state linearised about, with the accelerations and multipliers used
  Eigen::SparseMatrix<double> K;  ///< stiffness (num_kinematic x num_kinematic)
  Eigen::SparseMatrix<double> D;  ///< damping and gyroscopic terms (num_kinematic x num_kinematic)
  Eigen::SparseMatrix<double> M;  ///< mass (num_kinematic x num_kinematic); zero on joint variables
  Eigen::SparseMatrix<double> B;  ///< constraint Jacobian (num_multipliers x num_kinematic)
  Eigen::SparseMatrix<double> C;  ///< d(constraint rows)/d(multipliers) (num_multipliers x num_multipliers): 1 on
                                  ///< the rows of inactive constraints (an open rigid stop's lambda = 0), whose B
                                  ///< rows are empty; a Newton solve for the multipliers needs them
  Eigen::SparseMatrix<double> T;  ///< x = T y: node rotation matrices on translations, identity elsewhere
  Eigen::VectorXd residual;       ///< at the reference: force rows turned by T^T, then constraint rows
};

/// The state with accelerations (a_prev, alpha_prev, qddot_prev) and multipliers that satisfy the equations of
/// motion at its positions and velocities (theory (E2)); also a good start for a static solution, whose
/// first tangent lacks the geometric stiffness of the joints if the multipliers are zero. Throws SolverError
/// as EigenAnalysis does for a motion without inertia.
State WithConsistentMotion(const Model& model, const State& state);

/// Linearises the model about `state` (positions, rotations, velocities; accelerations and multipliers as
/// `reference` says). Throws SolverError if the accelerations cannot be solved for (see EigenAnalysis).
LinearisedSystem Linearise(const Model& model, const State& state, ReferenceMotion reference);

/// Solves the eigenproblem of a linearised system. Throws SolverError when the mass matrix reduced to the
/// constrained motions is not positive definite (a motion without inertia, e.g. a joint variable that moves
/// no body), naming the unknown that moves most in that motion, or when the sparse factorisation fails.
EigenResult SolveModes(const Model& model, const LinearisedSystem& system, const EigenOptions& options);

/// Linearise, then SolveModes.
EigenResult EigenAnalysis(const Model& model, const State& state, const EigenOptions& options);

/// The state with every velocity (node v and w, joint rates) multiplied by `factor` and every stored
/// acceleration by factor^2: the same motion run `factor` times faster (a rotor speed for a fan plot).
State ScaleVelocities(const State& state, double factor);

/// One parameter value of a sweep and its modes.
struct SweepPoint {
  double parameter = 0.0;
  EigenResult result;
};

/// Eigen-analysis of one model about the state `state_at(p)` for every parameter value p, in order. Modes
/// are then tracked from one point to the next (TrackModes).
std::vector<SweepPoint> EigenSweep(const Model& model, const std::vector<double>& parameters,
                                   const std::function<State(double)>& state_at, const EigenOptions& options);

/// A model and the state to linearise it about, for sweeps whose parameter changes the model.
struct SweepCase {
  Model model;
  State state;
};

/// As above, with a model built for each parameter value (a stiffness scale, a mass).
std::vector<SweepPoint> EigenSweep(const std::vector<double>& parameters,
                                   const std::function<SweepCase(double)>& case_at, const EigenOptions& options);

/// Reorders the modes of each point after the first so that mode k follows mode k of the previous point
/// (largest modal assurance criterion |x_a^H x_b|^2 / (|x_a|^2 |x_b|^2) over the node and joint unknowns, not the
/// element states, assigned greedily), so that a fan plot's lines cross instead of swapping. Points whose shapes
/// have another size are left as they are.
void TrackModes(std::vector<SweepPoint>* points);

/// True for a mode growing in time: Re s above the solver's round-off in it, growth_round_off (rigid-body modes are
/// not unstable).
bool Unstable(const Mode& mode);

/// A table with one line per mode: index, frequency [Hz], damped frequency [Hz], damping ratio, remark.
std::string FormatModeTable(const EigenResult& result);

/// A fan-plot table: one line per parameter value, its frequencies [Hz] of the first `num_modes` modes
/// (all if 0), then their damping ratios; columns apart by `separator` (a space, or a comma for a CSV file).
std::string FormatFanPlot(const std::vector<SweepPoint>& points, const std::string& parameter_name, int num_modes,
                          char separator = ' ');

}  // namespace flexmbd
