#pragma once
/// @file
/// Readers of the sections of the YAML extension parameters (docs/config.md). Each checks its keys against
/// its own table, reads every value through yaml_fields.hpp and overwrites only what the YAML gives.

#include <set>
#include <string>
#include <vector>

#include "flexmbd/io/urdf_reader.hpp"
#include "flexmbd/io/yaml_fields.hpp"
#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace io {

/// Units and description of one joint variable, from whether the kinematics rotate about it.
struct VariableUnits {
  Measure measure;
  std::string position;   ///< "rad" or "m"
  std::string stiffness;  ///< "N m/rad" or "N/m"
  std::string damping;    ///< "N m s/rad" or "N s/m"
};
VariableUnits UnitsOf(const JointSpec& joint, int variable);

/// `backlash:` of `variable` of `joint`: a map (a lower and/or an upper stop), or a list of such maps; stop
/// positions from the URDF <limit> when a block gives neither. A stop given outside the <limit> adds a warning.
std::vector<StopSpec> ReadBacklash(const Field& backlash, const JointSpec& joint, int variable,
                                   const VariableUnits& units, std::vector<std::string>* warnings);

/// Fails at `drive` if the drive of a variable (its path up to `t_end`, 0 for a static or eigen-analysis) passes
/// one of its rigid stops that does not retract: the run would stop there on a singular matrix.
void CheckDriveWithinRigidStops(const Field& drive, const VariableEffectsSpec& effects, double t_end,
                                const std::string& unit);

/// `friction:` of one joint variable: Coulomb friction with sticking (or the regularised law).
FrictionSpec ReadFriction(const Field& friction, const VariableUnits& units);

/// A joint's `type`, `axis`, `axis2` and `pitch` (each overwriting what the joint has), checked, and its
/// per-variable vectors sized to the type.
void ReadJointGeometry(const Field& field, JointSpec* joint);

/// `closures:` joints that close kinematic loops, appended to model->spec.joints (read before `joints:`, which
/// may configure their effects); their child side is set once the bodies are placed (CloseLoops).
void ReadClosures(const Field& closures, UrdfModel* model);

/// `joints:` a map from URDF joint names to joint settings (type, axes, pitch, effects, initial motion), checked
/// against the URDF <limit>s (urdf_limit.hpp) with drives up to solver.t_end (solver read first).
void ReadJoints(const Field& joints, UrdfModel* model);

/// The link names under `beams:` (read before the URDF, which needs to know which links are beams).
std::set<std::string> BeamLinkNames(const YAML::Node& params, const std::string& params_name);

/// `beams:` a map from URDF link names to beam settings (length, elements, order, section).
void ReadBeams(const Field& beams, UrdfModel* model);

/// `solver:` settings, then the consistency dt_min <= dt <= dt_max.
void ReadSolver(const Field& solver, SolverSpec* spec);

/// `output:` settings; `output.cycle_from` must lie before t_end (solver read first).
void ReadOutput(const Field& output, double t_end, OutputSpec* spec);

/// `output.beam_stations`: beam name -> distances from the root in [0, length] [m] (beams read first).
void ReadBeamStations(const Field& output, const UrdfModel& model, OutputSpec* spec);

/// `output.strip_stations`: aero.strips name -> distances from the root of its beam in [0, length] [m] (beams and
/// aero read first).
void ReadStripStations(const Field& output, const UrdfModel& model, OutputSpec* spec);

/// `loads:` a list of forces and moments on bodies of `model`.
void ReadLoads(const Field& loads, const UrdfModel& model, std::vector<LoadSpec>* specs);

/// `aero:` the typical sections (on joints of `model`) and the strips along its beams that carry unsteady
/// thin-airfoil loads, and the free stream, density and gust the strips move in (beams read first).
void ReadAero(const Field& aero, UrdfModel* model);

/// Fails at solver.eigen.sweep.airspeed if it is given and the model has no aero sections or strips to blow on, or
/// strips without the free stream's direction.
void CheckAirspeedSweep(const Field& root, const ModelSpec& spec);

/// Fails at a joint variable's non-zero initial velocity (not a drive's) when solver.static_first (dynamic) or
/// solver.eigen.static_first (eigen) starts from the static equilibrium, which is at rest.
void CheckStaticStart(const Field& root, const ModelSpec& spec);

/// A time function: `law` (required) and the keys that law takes. Values are in `unit` (SI; "" for a plain
/// factor) or, if `measure` is angular, in degrees under `<key>_deg`; `phase_deg` is always allowed.
TimeFunctionSpec ReadTimeFunction(const Field& map, const std::string& unit, const Measure& measure);

}  // namespace io
}  // namespace flexmbd
