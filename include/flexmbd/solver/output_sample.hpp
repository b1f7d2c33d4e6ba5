#pragma once
/// @file
/// One output sample: what every sink (CSV, bag, topics) receives. One conversion, several sinks.

#include <vector>

#include <Eigen/Core>

#include "flexmbd/elements/element.hpp"

namespace flexmbd {

class Model;

/// One stop of a joint (backlash) at a sample.
struct StopSample {
  bool in_contact = false;
  double force = 0;     ///< contact force, >= 0 [N]
  double torque = 0;    ///< its generalised force on the joint variable [N m, or N on a prismatic joint]
  double approach = 0;  ///< penetration of a deformable stop, > 0 in contact; 0 for a rigid stop [m]
};

/// The friction of one joint at a sample.
struct FrictionSample {
  bool sticking = false;
  double torque = 0;         ///< friction force on the joint variable [N m, or N on a prismatic joint]
  double normal_force = 0;   ///< radial reaction plus preload [N]
  double slip_velocity = 0;  ///< relative velocity at the races, radius times the variable's rate [m/s]
  double work = 0;           ///< cumulative energy dissipated by this joint's friction [J]
  /// The step that led to the sample held the joint by its sticking row, so its torque is the sticking force (a
  /// capture's too, which begins the step sliding): what a sample inside the step says (not written to the sinks)
  bool step_stuck = false;
};

/// One station of output.beam_stations at a sample (docs/theory.md, "Station outputs").
struct BeamStationSample {
  Vec6 load = Vec6::Zero();       ///< section forces and moments (N, V2, V3, T, M2, M3), section frame [N, N m]
  Vec6 strain = Vec6::Zero();     ///< strains and curvatures (eps1, gamma2, gamma3, kappa1..3), section frame [-, 1/m]
  Vec3 displacement = Vec3::Zero();  ///< of the beam axis from its initial position, in W [m]
  Vec3 rotation = Vec3::Zero();      ///< rotation vector of R_W(s) R_W0(s)^T, in W [rad]
  Vec3 velocity = Vec3::Zero();      ///< of the beam axis, in W [m/s]: the displacement's slope between samples (not
                                     ///< written to the sinks)
};

/// One aero section (aero.sections) at a sample: the loads of TypicalSectionAero::SectionLoads over its span, as
/// the step that produced the sample applied them, and its inflow states. A station along strips
/// (output.strip_stations) has the same values per unit span [N/m, N m/m], interpolated between its two nodes'
/// strips (BeamStripAero::StripLoads over their lengths).
struct AeroSectionSample {
  double lift = 0;          ///< along the chord normal [N]
  double moment = 0;        ///< about the elastic axis, nose up [N m]
  double hinge_moment = 0;  ///< about the flap hinge, trailing edge down [N m]
  Eigen::VectorXd inflow;   ///< Peters' states mu_1..mu_N (docs/theory.md, (A6), (A9)) [m/s]
};

/// One rotor (aero.rotors) at a sample (docs/theory.md, (A13), (A14)).
struct AeroRotorSample {
  double inflow = 0;  ///< the induced velocity nu (nu_0 with harmonics) through the disc, along -axis [m/s]
  double thrust = 0;  ///< the blades' strips' lift along the axis [N]
  /// With harmonics: nu_c, nu_s [m/s] and the lift's moments about the centre M_c, M_s [N m] (zero without)
  double inflow_cos = 0, inflow_sin = 0, moment_cos = 0, moment_sin = 0;
};

struct OutputSample {
  double t = 0;                  ///< [s]
  Eigen::VectorXd position;      ///< joint variables [rad or m] (num_variables)
  Eigen::VectorXd velocity;      ///< their rates [rad/s or m/s]
  Eigen::VectorXd effort;        ///< generalised force along each variable, stops and friction included [N m or N]
  std::vector<Vec3> reaction_force_W;   ///< per joint: force on the child from the parent, in W [N]
  std::vector<Vec3> reaction_moment;    ///< per joint: rotational multipliers (moment on the child) [N m]
  std::vector<StopSample> stops;         ///< per stop, in Model::stops() order
  std::vector<FrictionSample> friction;  ///< per frictional joint, in Model::frictions() order
  std::vector<BeamStationSample> beam_stations;  ///< per station, in Model::beam_stations() order
  std::vector<AeroSectionSample> aero_sections;  ///< per section, in Model::aero_sections() order
  std::vector<AeroSectionSample> strip_stations;  ///< per unit span, in Model::strip_stations() order
  std::vector<AeroRotorSample> aero_rotors;       ///< in Model::aero_rotors() order
  double kinetic = 0;            ///< [J]
  double potential = 0;          ///< gravity, springs and beam strain energy [J]
  double external_work = 0;      ///< cumulative work of applied loads, drives and commanded efforts [J]
  double dissipated = 0;         ///< cumulative energy dissipated by dampers, friction, stop and beam damping [J]
  double numerical_dissipation = 0;  ///< cumulative energy removed by the integrator [J]
  double dt = 0;                 ///< size of the step that produced the sample [s]
  int iterations = 0;            ///< Newton iterations of that step
  double total() const { return kinetic + potential; }
};

/// Kinetic and potential energy of the model's elements at `state`.
EnergyTally StateEnergy(const Model& model, const State& state);

/// The sample at a state; efforts and reactions come from the multipliers evaluated in `ctx`.
OutputSample MakeSample(const Model& model, const State& state, const StepContext& ctx, double dt, int iterations);

/// The sample at time t in [a.t, b.t] between two samples: linear (MixLinearQuantities), except the joint variables
/// and beam stations' displacements (cubic Hermite from their end velocities), stations' rotations (on SO(3), at a
/// constant rate from a's to b's) (docs/theory.md, "Station outputs"), contacts (the nearer sample's) and friction
/// (the step's forces, b's, in the step's mode).
OutputSample Interpolate(const OutputSample& a, const OutputSample& b, double t);

/// Sets in *s the quantities of a sample that Interpolate takes linear in time, (1 - u) a + u b: velocities, efforts,
/// reactions, energies, stations' loads, strains and velocities, aero sections', strips' and rotors' values. The
/// rest of *s (positions, stations' displacements and rotations, contacts, friction) is left as it is.
void MixLinearQuantities(const OutputSample& a, const OutputSample& b, double u, OutputSample* s);

}  // namespace flexmbd
