#pragma once
/// @file
/// Plain-data description of a mechanism, produced by the loader (URDF + YAML) or written by hand in
/// tests, and turned into a frozen Model by BuildModel(). No behaviour lives here.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace flexmbd {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// A time function f(t), used by drives and applied loads (docs/config.md, "time functions").
struct TimeFunctionSpec {
  enum class Kind { kConstant, kLinearRamp, kCosineRamp, kRateRamp, kSine, kTable };
  Kind kind = Kind::kConstant;
  double value = 0.0;      ///< constant value, or the value reached by a ramp (SI units of the driven quantity);
                           ///< kRateRamp: the rate reached (SI units per second)
  double start = 0.0;      ///< time at which a ramp or sine begins [s]
  double duration = 1.0;   ///< ramp duration [s]
  double offset = 0.0;     ///< value before the ramp starts, and mean of the sine
  double amplitude = 0.0;  ///< sine amplitude
  double frequency = 0.0;  ///< sine frequency [Hz]
  double phase = 0.0;      ///< sine phase [rad]
  std::vector<double> times;   ///< table abscissae [s], strictly increasing
  std::vector<double> values;  ///< table ordinates, same size as times
};

/// A rigid body. Its reference frame B is the URDF link frame; the solver places its node at the centre of mass.
struct BodySpec {
  std::string name;
  double mass = 0.0;                           ///< [kg]
  Mat3 inertia_cm_B = Mat3::Zero();            ///< inertia tensor about the centre of mass, in B [kg m^2]
  Vec3 p_BoBcm_B = Vec3::Zero();               ///< centre of mass offset from the B origin, in B [m]
  Vec3 p_WB = Vec3::Zero();                    ///< initial position of the B origin in the world [m]
  Mat3 R_WB = Mat3::Identity();                ///< initial orientation of B in the world
  Vec3 v_WBo_W = Vec3::Zero();                 ///< initial velocity of the B origin, in W [m/s]
  Vec3 w_WB_W = Vec3::Zero();                  ///< initial angular velocity of B, in W [rad/s]
};

/// Joint types; each has the relative-motion variables listed in docs/theory.md.
enum class JointType { kRevolute, kPrismatic, kCylindrical, kScrew, kPlanar, kSpherical, kUniversal, kFixed };

/// A linear spring on one relative-motion variable: Q = -k (q - rest).
struct SpringSpec {
  double stiffness = 0.0;  ///< [N m/rad] or [N/m]
  double rest = 0.0;       ///< [rad] or [m]
};

/// A viscous damper on one relative-motion variable: Q = -c qdot.
struct DamperSpec {
  double coefficient = 0.0;  ///< [N m s/rad] or [N s/m]
};

/// A stop on one relative-motion variable q (backlash, freeplay; docs/theory.md, "Stops"). Its gap is
/// g = radius (upper - q) for an upper stop and g = radius (q - lower) for a lower one; contact when g <= 0.
struct StopSpec {
  enum class Side { kLower, kUpper };
  enum class Kind { kRigid, kElastic };
  enum class Law { kLinear, kHertz };
  std::string name;              ///< "lower" or "upper", with ".<k>" for the k-th backlash block (k >= 1)
  Side side = Side::kUpper;
  double limit = 0.0;            ///< stop position [rad or m]
  double radius = 1.0;           ///< contact radius [m]; 1 on a prismatic variable (the gap is the travel)
  Kind kind = Kind::kRigid;
  Law law = Law::kHertz;         ///< elastic stops: force k a (linear) or k a^n (Hertz) at approach a
  double stiffness = 0.0;        ///< elastic stops [N/m^n]
  double exponent = 1.5;         ///< Hertz exponent n
  double restitution = 1.0;      ///< coefficient of restitution e in (0, 1] (Hunt-Crossley dissipation)
  int steps_per_contact = 20;    ///< elastic stops: smallest number of steps that resolve one impact
  /// A conditional stop retracts (stops acting) at the first separation after |rate of `joint`| exceeds
  /// `retract_above`, and engages again once it falls below `engage_below` (when the gap is open).
  struct Retraction {
    std::string joint;           ///< empty: the stop never retracts
    int variable = -1;           ///< filled by BuildModel
    double retract_above = 0.0;  ///< [rad/s or m/s]
    double engage_below = 0.0;   ///< [rad/s or m/s], < retract_above
  };
  Retraction retraction;
};

/// Coulomb friction on one relative-motion variable (docs/theory.md, "Friction").
struct FrictionSpec {
  enum class Law {
    kCoulombStick,   ///< sliding T = -mu_k rho N sign(v), sticking constraint while |T| <= mu_s rho N
    kRegularised,    ///< T = -mu_k rho N (1 - exp(-|v|/v0)) sign(v), no sticking
    kConstantTorque  ///< |T| <= torque: Coulomb with a fixed bound (URDF <dynamics friction>)
  };
  Law law = Law::kCoulombStick;
  double mu_s = 0.0, mu_k = 0.0;  ///< static and kinetic coefficients, mu_s >= mu_k >= 0
  double radius = 1.0;            ///< race radius rho [m] (1 on a prismatic variable)
  double preload = 0.0;           ///< normal force added to the joint's radial reaction [N]
  double v0 = 0.0;                ///< sticking threshold on the slip velocity [m/s]; 0: from error_tol
  double torque = 0.0;            ///< kConstantTorque: the friction bound [N m or N]
};

/// Effects acting on one relative-motion variable of a joint.
struct VariableEffectsSpec {
  std::vector<SpringSpec> springs;
  std::vector<DamperSpec> dampers;
  std::vector<TimeFunctionSpec> drives;  ///< at most one: the variable then follows f(t) exactly
  std::vector<StopSpec> stops;
  std::vector<FrictionSpec> frictions;   ///< at most one
  bool static_hold = false;              ///< held at its initial position in the static analysis, free after it
};

/// A joint between a frame J_P on the parent body (or the world) and a frame J_C on the child body.
/// At zero relative motion the two frames coincide.
struct JointSpec {
  std::string name;
  JointType type = JointType::kRevolute;
  std::string parent;                           ///< parent body name; empty for the world
  std::string child;                            ///< child body name
  Vec3 p_PJ = Vec3::Zero();                     ///< joint frame origin in the parent frame [m]
  Mat3 R_PJ = Mat3::Identity();                 ///< joint frame orientation in the parent frame
  Vec3 p_CJ = Vec3::Zero();                     ///< joint frame origin in the child frame [m]
  Mat3 R_CJ = Mat3::Identity();                 ///< joint frame orientation in the child frame
  Vec3 axis_J = Vec3::UnitZ();                  ///< motion axis in the joint frame (normal for planar)
  Vec3 axis2_J = Vec3::UnitX();                 ///< second axis of a universal joint, in the joint frame
  double pitch = 0.0;                           ///< screw pitch [m/rev]
  std::vector<double> initial_position;         ///< initial relative motion, one per variable [rad or m]
  std::vector<double> initial_velocity;         ///< initial relative rate, one per variable [rad/s or m/s]
  std::vector<VariableEffectsSpec> effects;     ///< one entry per variable (may be empty)
  /// Per variable: the YAML sets its initial position (`initial.position` or a drive at t = 0), which the
  /// assembly of loops holds; the others it may move (docs/theory.md, "Assembly of the initial configuration").
  std::vector<bool> position_set;
  std::vector<bool> velocity_set;  ///< per variable: the YAML sets its initial rate (as position_set)
  /// A spherical joint's initial relative rotation R_JpJc and angular velocity w_JpJc (in Jp), which no variable
  /// carries: the assembly of loops sets them; identity and zero otherwise.
  Mat3 initial_rotation = Mat3::Identity();
  Vec3 initial_angular_velocity = Vec3::Zero();  ///< [rad/s]
  bool has_limits = false;                      ///< URDF <limit> given (used by backlash without angles)
  double limit_lower = 0.0, limit_upper = 0.0;  ///< URDF <limit> lower and upper [rad or m]
  /// The URDF gave a <limit> in the other unit than the YAML type's variable 0 (a revolute's radians on a joint made
  /// prismatic): left out, has_limits is false (io::LeaveOutLimitOfAnotherUnit)
  bool limit_of_another_unit = false;
  /// A joint of YAML `closures:` that closes a kinematic loop: not part of the tree that places the bodies;
  /// its initial variables are those that put its child frame where the tree placed it (docs/config.md).
  bool closes_loop = false;
};

/// Sectional properties of a beam, in the section frame (x along the beam axis).
struct BeamSectionSpec {
  /// 6x6 stiffness from (axial strain, shear strains y z, twist, curvatures about y z) to (axial force, shear
  /// forces, torque, bending moments) [N, N m^2 ...]; full, with the couplings of composite sections.
  Eigen::Matrix<double, 6, 6> stiffness = Eigen::Matrix<double, 6, 6>::Zero();
  double mass_per_length = 0.0;            ///< [kg/m]
  Vec3 inertia_per_length = Vec3::Zero();  ///< (torsional, about y, about z) mass moments per length about the
                                           ///< centre of mass [kg m]
  /// Centre of mass (y, z) in the section frame, from the beam axis [m] (docs/theory.md, (B6)).
  Eigen::Vector2d cg_offset = Eigen::Vector2d::Zero();
  /// Shear centre (y, z) in the section frame, from the beam axis [m]: the shear stiffnesses act there, the
  /// axial and bending ones on the beam axis (docs/theory.md, (B8)).
  Eigen::Vector2d shear_center_offset = Eigen::Vector2d::Zero();
};

/// A geometrically exact beam along the x axis of a link frame B, from the B origin (docs/config.md, "beams").
struct BeamSpec {
  std::string name;           ///< the URDF link it replaces
  double length = 0.0;        ///< [m]
  int elements = 1;           ///< number of elements, >= 1
  int order = 3;              ///< shape-function order 1..3 (nodes per element = order + 1)
  double damping = 0.0;       ///< structural damping mu >= 0: section forces mu C eps_dot [s] (theory (B7))
  BeamSectionSpec section;
  Vec3 p_WB = Vec3::Zero();        ///< initial position of the B origin [m]
  Mat3 R_WB = Mat3::Identity();    ///< initial orientation of B
  Vec3 v_WBo_W = Vec3::Zero();     ///< initial velocity of the B origin [m/s]
  Vec3 w_WB_W = Vec3::Zero();      ///< initial angular velocity of B (rigid initial motion) [rad/s]
};

/// A force or moment applied to a body, scaled by a time function.
struct LoadSpec {
  enum class Kind { kForce, kMoment };
  enum class Frame { kWorld, kBody };  ///< kWorld: dead load; kBody: follower load
  std::string body;
  Kind kind = Kind::kForce;
  Frame frame = Frame::kWorld;
  Vec3 vector = Vec3::Zero();           ///< [N] or [N m], in the chosen frame
  Vec3 p_BoP_B = Vec3::Zero();          ///< point of application of a force, in B [m]
  /// Per unit length, uniform along the whole beam `body` (vector in N/m or N m/m; kBody: the section frame);
  /// consistent nodal loads (docs/theory.md, (B9)).
  bool distributed = false;
  TimeFunctionSpec scale;               ///< multiplies vector; constant 1 by default
  LoadSpec() { scale.value = 1.0; }
};

/// Solver settings (docs/config.md, "solver").
struct SolverSpec {
  enum class Analysis { kDynamic, kStatic, kEigen };
  enum class Integrator { kEnergyDecaying, kEnergyPreserving, kGeneralizedAlpha };
  Analysis analysis = Analysis::kDynamic;
  Integrator integrator = Integrator::kEnergyDecaying;
  /// High-frequency amplification per step: energy-decaying [1/3, 1], generalized-alpha [0, 1].
  double rho_inf = 0.6;
  double t_end = 1.0;              ///< [s]
  double dt = 1.0e-2;              ///< initial (and, without adaptivity, fixed) step [s]
  double dt_min = 1.0e-7;          ///< [s]; unset in YAML: this times error_tol / 1e-4 in [1e-3, 1]
  double dt_max = 0.1;             ///< [s]
  bool adaptive = true;            ///< adapt the step to the local error estimate
  double tol = 1.0e-6;             ///< Newton relative tolerance
  double error_tol = 1.0e-4;       ///< local error target per step, relative
  /// Absolute floors of the local error test per step (docs/theory.md, (T12)); 0 takes error_tol / 1000 of the
  /// model's length scale (position) or of one radian (rotation; joint variables, in their own units).
  struct ErrorFloors {
    double position = 0;  ///< [m]
    double rotation = 0;  ///< [rad]
    double joint = 0;     ///< [rad or m]
  };
  ErrorFloors error_floor;
  int max_iterations = 20;         ///< Newton iterations per step
  int load_steps = 10;             ///< load increments of the static analysis
  int threads = 1;                 ///< threads evaluating the elements (1: the calling thread alone)
  bool static_first = false;       ///< run a static analysis and start the dynamics from it
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);  ///< [m/s^2]
  /// Eigen-analysis settings (docs/config.md, "solver.eigen"; docs/theory.md, "Eigen-analysis").
  struct EigenSettings {
    enum class Method { kAuto, kDense, kSparse };
    /// The state linearised about: the initial one (or its static equilibrium), or the steady rotation at the
    /// initial rate of the spinning joint (docs/theory.md, "Steady rotation").
    enum class About { kInitialState, kSteadyState };
    About about = About::kInitialState;
    int modes = 0;                 ///< modes reported, lowest first; 0 reports all (dense) or 10 (sparse)
    bool static_first = false;     ///< linearise about the static equilibrium instead of the initial state
    Method method = Method::kAuto; ///< dense below 2000 node and variable unknowns, sparse shift-invert above
    double shift_hz = 0.0;         ///< sparse: seek the modes nearest this frequency [Hz]; 0 = the lowest
    std::vector<double> sweep_velocity_scale;  ///< fan plot: factors on every initial velocity; empty for none
    /// Fan plot over the free-stream speed of every aero section, increasing [m/s]; empty for none. The runner
    /// locates where a mode's damping ratio changes sign (docs/theory.md, "Flutter speed" (E9)).
    std::vector<double> sweep_airspeed;
    /// A dynamic run lands a step on each of these times and reports the modes about the state there
    /// (docs/theory.md, "Eigen-analysis at a time of a run") [s]; increasing, in [0, t_end]; empty for none.
    std::vector<double> at_times;
  };
  EigenSettings eigen;             ///< used when analysis is kEigen, and at_times by a dynamic run
};

/// Output settings (docs/config.md, "output").
struct OutputSpec {
  double rate_hz = 100.0;  ///< sample rate; 0 writes every accepted step
  std::string csv;         ///< CSV path; empty for none
  std::string bag;         ///< bag path; empty for none
  /// Beam name -> stations, distances from the root in [0, length] [m], sampled in OutputSample::beam_stations.
  std::map<std::string, std::vector<double>> beam_stations;
  /// aero.strips name -> stations along its beam, distances from the root in [0, length] [m], sampled in
  /// OutputSample::strip_stations.
  std::map<std::string, std::vector<double>> strip_stations;
  /// Allow a run to write more than kMaxOutputValues values to its CSV or bag (model/output_size.hpp).
  bool allow_large_output = false;
  /// The runner reports the amplitude and frequency of every joint variable over [cycle_from, t_end] (a limit
  /// cycle's, docs/config.md) [s]; negative: no report.
  double cycle_from = -1.0;
};

/// A typical section carrying unsteady thin-airfoil loads (docs/config.md, "aero"; docs/theory.md, (A1)-(A6)):
/// three joints give its plunge, pitch and flap; the free stream blows along +x of the world, lift along +z.
struct AeroSectionSpec {
  std::string name;
  std::string plunge, pitch, flap;  ///< joint names: prismatic (plunge), revolutes (pitch, flap)
  double semichord = 0.0;           ///< b [m]
  double a = 0.0;                   ///< elastic axis (the pitch joint) at a b aft of mid-chord, -1 < a < 1
  double c = 0.0;                   ///< flap hinge at c b aft of mid-chord, -1 < c < 1
  double span = 1.0;                ///< the section's span: the loads are per unit span times this [m]
  double velocity = 0.0;            ///< free-stream speed U [m/s]
  double density = 1.225;           ///< air density rho [kg/m^3]
  int inflow_states = 6;            ///< Peters' induced-flow states N (0: quasi-steady)
};

/// Strips of thin-airfoil loads along a beam (docs/config.md, "aero"; docs/theory.md, (A7)-(A9)): one strip per
/// node of the beam, as long as the node's lumped length, in the air of AeroFlowSpec. The beam axis is the
/// elastic axis and lies on the chord line.
struct AeroStripSpec {
  std::string name;
  std::string beam;                       ///< the beam (a link under beams:) carrying the strips
  double semichord = 0.0;                 ///< b [m]
  double a = 0.0;                         ///< the beam axis (elastic axis) at a b aft of mid-chord, -1 < a < 1
  Vec3 chord_axis = Vec3::UnitY();        ///< unit vector from leading to trailing edge, in the section frame
  Vec3 normal_axis = Vec3::UnitZ();       ///< unit normal of the chord (the lift direction), in the section frame
  int inflow_states = 6;                  ///< Peters' induced-flow states N per strip (0: quasi-steady)
  /// The trailing-edge flap (docs/theory.md, (A10)): a beam along the hinge line whose nodes stand at some of
  /// the strips' stations; empty beam: no flap.
  struct Flap {
    std::string beam;  ///< the control surface's beam
    double c = 0.0;    ///< the hinge at c b aft of mid-chord, a < c < 1
  } flap;
};

/// The air the strips move in (docs/config.md, "aero").
struct AeroFlowSpec {
  Vec3 free_stream = Vec3::Zero();  ///< velocity of the air far from the wing, in W [m/s]
  double density = 1.225;           ///< rho [kg/m^3]
  Vec3 gust = Vec3::Zero();         ///< uniform gust velocity in W, added to the free stream times gust_scale [m/s]
  TimeFunctionSpec gust_scale;      ///< constant 1 by default
  AeroFlowSpec() { gust_scale.value = 1.0; }
};

/// A rotor's induced inflow (docs/config.md, "aero"; docs/theory.md, (A13), (A14)): the induced velocity through
/// the disc, uniform (one state nu, driven by the thrust of the rotor's strips) or with Pitt-Peters' first harmonics
/// over the disc (three states, driven by the thrust and the strips' moments about the centre), blown through every
/// strip of the rotor.
struct AeroRotorSpec {
  enum class Inflow { kUniform, kHarmonic };
  std::string name;
  std::vector<std::string> strips;  ///< names under aero.strips: the blades
  double radius = 0.0;              ///< R [m]: the disc's area pi R^2 and its air's apparent mass (8/3) rho R^3
  Vec3 axis = Vec3::UnitZ();        ///< unit shaft axis in W, along the thrust; the inflow blows along -axis
  Inflow inflow = Inflow::kUniform;
  Vec3 center = Vec3::Zero();       ///< the disc's centre in W [m], on the shaft axis (the harmonics' origin)
};

class Element;
class Model;

/// An element written in C++ by a program that embeds the core (and by tests of the element interface): made
/// once the joints exist, so that it can look up the unknowns of the variables it acts on (Model::FindVariable,
/// Model::variable_unknown). It may own states (Element::num_states() == num_states); its first one is
/// Model::element_state_unknown(first_state).
struct CustomElementSpec {
  int num_states = 0;
  std::function<std::unique_ptr<Element>(const Model& model, int first_state)> make;
};

/// The whole mechanism and its run settings.
struct ModelSpec {
  std::string source;  ///< where it came from (file names), used in messages
  std::vector<BodySpec> bodies;
  std::vector<BeamSpec> beams;
  std::vector<JointSpec> joints;
  std::vector<LoadSpec> loads;
  std::vector<AeroSectionSpec> aero_sections;
  std::vector<AeroStripSpec> aero_strips;
  std::vector<AeroRotorSpec> aero_rotors;
  AeroFlowSpec aero_flow;
  std::vector<CustomElementSpec> custom_elements;
  SolverSpec solver;
  OutputSpec output;
  /// What the loader accepted but doubts (a stop outside the URDF <limit>), one line each naming the file and
  /// field; the runner prints them to stderr, the node as ROS_WARN.
  std::vector<std::string> warnings;
};

/// Number of relative-motion variables of a joint type.
int NumJointVariables(JointType type);

/// Lower-case name of a joint type as written in YAML ("revolute", ...).
const char* JointTypeName(JointType type);

}  // namespace flexmbd
