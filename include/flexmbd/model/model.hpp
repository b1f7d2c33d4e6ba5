#pragma once
/// @file
/// Model: what does not change during a run, frozen at build: nodes, elements, the unknown layout and the
/// initial State. Unknowns are ordered [node increments (6 per node) | joint variables | element states |
/// multipliers] (docs/theory.md, "Unknowns"; element states: (S1)).

#include <memory>
#include <string>
#include <vector>

#include "flexmbd/aero/beam_strip_aero.hpp"
#include "flexmbd/aero/rotor_inflow.hpp"
#include "flexmbd/aero/typical_section_aero.hpp"
#include "flexmbd/effects/friction_effect.hpp"
#include "flexmbd/effects/joint_stop.hpp"
#include "flexmbd/effects/modal_effect.hpp"
#include "flexmbd/effects/variable_effects.hpp"
#include "flexmbd/elements/beam_element.hpp"
#include "flexmbd/elements/element.hpp"
#include "flexmbd/elements/rigid_body.hpp"
#include "flexmbd/joints/joint.hpp"
#include "flexmbd/model/model_spec.hpp"
#include "flexmbd/model/state.hpp"

namespace flexmbd {

/// A rigid body as the user named it: its node sits at the centre of mass.
struct BodyInfo {
  std::string name;
  int node = -1;
  Vec3 p_NBo_N = Vec3::Zero();  ///< body (link) frame origin relative to the node, in the node frame [m]
};

/// A beam as the user named it: its nodes along the link's x axis and its elements.
struct BeamInfo {
  std::string name;
  std::vector<int> nodes;                    ///< node indices from root to tip
  std::vector<double> stations;              ///< their distance from the root [m]
  std::vector<double> lumped_lengths;        ///< share of the length lumped on each node [m] (theory (B6))
  std::vector<const BeamElement*> elements;  ///< from root to tip
  double damping = 0.0;                      ///< structural damping mu [s] (theory (B7))
};

/// A station of `output.beam_stations`: where on which element it is sampled.
struct BeamStationInfo {
  std::string beam;                   ///< beam name
  int index = 0;                      ///< k in the output names beam.<name>.s<k>
  double s = 0.0;                     ///< distance from the root [m]
  const BeamElement* element = nullptr;
  double s_element = 0.0;             ///< distance from the element's first node [m]
};

/// A station of `output.strip_stations`: the two strips (nodes) of an aero.strips entry either side of it, whose
/// loads per unit span and inflow states it interpolates linearly.
struct StripStationInfo {
  std::string strip;                     ///< the aero.strips name
  int index = 0;                         ///< k in the output names strip.<name>.s<k>
  double s = 0.0;                        ///< distance from the beam's root [m]
  const BeamStripAero* inner = nullptr;  ///< the strip at the node at or root-side of s
  const BeamStripAero* outer = nullptr;  ///< the strip at the next node tip-side (inner itself at the tip)
  double weight = 0.0;                   ///< outer's share, in [0, 1]
};

/// A stop (backlash) as the user named it.
struct StopInfo {
  std::string joint;  ///< its variable's name: the joint's, or joint/k on the k-th variable of a multi-variable joint
  std::string stop;   ///< "lower", "upper", or the name given in YAML
  int variable = -1;  ///< the joint variable it acts on
};

/// A frictional joint as the user named it.
struct FrictionInfo {
  std::string joint;
  int variable = -1;
};

class Model {
 public:
  int num_nodes() const { return num_nodes_; }
  /// "body <name>" or "beam <name> node <k>".
  const std::string& node_name(int node) const { return node_names_[node]; }
  int num_variables() const { return num_variables_; }
  int num_multipliers() const { return num_multipliers_; }
  /// Number of states the elements own (Element::num_states(), summed): State::element_states.
  int num_element_states() const { return num_element_states_; }
  int num_unknowns() const { return 6 * num_nodes_ + num_variables_ + num_element_states_ + num_multipliers_; }
  /// Node, joint variable and element state unknowns: the second-order ones (nodes, variables) and the
  /// first-order ones (element states), everything but the multipliers.
  int num_kinematic() const { return 6 * num_nodes_ + num_variables_ + num_element_states_; }
  int node_unknown(int node) const { return 6 * node; }
  int variable_unknown(int variable) const { return 6 * num_nodes_ + variable; }
  int element_state_unknown(int k) const { return 6 * num_nodes_ + num_variables_ + k; }
  int multiplier_unknown(int multiplier) const { return num_kinematic() + multiplier; }
  /// True for rows that are equations of motion: generalised-force balances (node and variable unknowns) and the
  /// elements' first-order state equations; false for constraints.
  bool is_force_row(int unknown) const { return unknown < num_kinematic(); }
  /// True for the rows (and unknowns) of element states.
  bool is_state_row(int unknown) const {
    return unknown >= 6 * num_nodes_ + num_variables_ && unknown < num_kinematic();
  }

  const std::vector<std::unique_ptr<Element>>& elements() const { return elements_; }
  const std::vector<const Joint*>& joints() const { return joints_; }
  const std::vector<const RigidBody*>& rigid_bodies() const { return rigid_bodies_; }
  const std::vector<BodyInfo>& bodies() const { return bodies_; }
  const std::vector<BeamInfo>& beams() const { return beams_; }
  /// Index in beams() of the beam a node belongs to, or -1 (a body, or a beam's centre-of-mass node).
  int beam_of_node(int node) const { return node_beams_[node]; }
  /// True for a beam node without rotary inertia (section m_ii 0, no centre-of-mass offset): the section's moments
  /// alone hold its rotation, an algebraic variable, which the midpoint equations leave with an alternating error
  /// (docs/theory.md, "Algebraic rotations").
  bool rotation_is_algebraic(int node) const { return algebraic_rotations_[node]; }
  /// True for a variable of a joint on such a node: the variable carries that node's alternating error.
  bool moves_with_algebraic_rotation(int variable) const { return on_algebraic_rotations_[variable]; }
  /// The stations of output.beam_stations, beam by beam (in name order), then in the order given.
  const std::vector<BeamStationInfo>& beam_stations() const { return beam_stations_; }
  const std::vector<StopInfo>& stops() const { return stops_; }
  /// The stop elements, in stops() order.
  const std::vector<const JointStop*>& stop_effects() const { return stop_effects_; }
  /// Every effect with modes; effect k keeps its mode in State::effects[k].
  const std::vector<const ModalEffect*>& modal_effects() const { return modal_effects_; }
  const std::vector<FrictionInfo>& frictions() const { return frictions_; }
  /// The aerodynamic sections (aero.sections), in the order given.
  const std::vector<const TypicalSectionAero*>& aero_sections() const { return aero_sections_; }
  /// The strips of aero.strips, strip by strip in the order given, each root to tip.
  const std::vector<const BeamStripAero*>& aero_strips() const { return aero_strips_; }
  /// The stations of output.strip_stations, strip by strip (in name order), then in the order given.
  const std::vector<StripStationInfo>& strip_stations() const { return strip_stations_; }
  /// The rotors' inflows (aero.rotors), in the order given.
  const std::vector<const RotorInflow*>& aero_rotors() const { return aero_rotors_; }
  /// The friction elements, in frictions() order.
  const std::vector<const FrictionEffect*>& friction_effects() const { return friction_effects_; }
  /// Name of each joint variable: the joint name, with "/k" appended for the k-th of several.
  const std::vector<std::string>& variable_names() const { return variable_names_; }
  /// Index of the joint variable named `name` (variable_names()), or -1 if there is none.
  int FindVariable(const std::string& name) const;
  /// True if a drive prescribes the motion of `variable` (it then takes set-points, State::commands).
  bool driven(int variable) const { return driven_[variable]; }

  /// The breakpoints of every time function (drives, load scales, the gust's scale), increasing, each once [s]: a
  /// run's steps land on them (docs/theory.md, "Breakpoints").
  const std::vector<double>& breakpoints() const { return breakpoints_; }

  const SolverSpec& solver() const { return solver_; }
  const OutputSpec& output() const { return output_; }
  const State& initial_state() const { return initial_state_; }
  const std::string& source() const { return source_; }
  /// Largest node distance from the origin in the initial state, at least 1 [m]: the scale of round-off.
  double length_scale() const { return length_scale_; }

  /// Human-readable name of an unknown, e.g. "body link1 rot_y", "beam panel_2 node 3 rot_y" or
  /// "joint B1 constraint 3".
  std::string DescribeUnknown(int unknown) const;

 private:
  friend Model BuildModel(const ModelSpec& spec);
  friend class VariableEffectsBuilder;  ///< BuildModel's helper for the effects on a joint variable
  int num_nodes_ = 0, num_variables_ = 0, num_element_states_ = 0, num_multipliers_ = 0;
  std::vector<std::unique_ptr<Element>> elements_;
  std::vector<const Joint*> joints_;
  std::vector<const RigidBody*> rigid_bodies_;
  std::vector<BodyInfo> bodies_;
  std::vector<BeamInfo> beams_;
  std::vector<int> node_beams_;  ///< beam_of_node, per node
  std::vector<bool> algebraic_rotations_;    ///< rotation_is_algebraic, per node
  std::vector<bool> on_algebraic_rotations_;  ///< moves_with_algebraic_rotation, per variable
  std::vector<BeamStationInfo> beam_stations_;
  std::vector<StopInfo> stops_;
  std::vector<const JointStop*> stop_effects_;
  std::vector<const ModalEffect*> modal_effects_;
  std::vector<FrictionInfo> frictions_;
  std::vector<const FrictionEffect*> friction_effects_;
  std::vector<const TypicalSectionAero*> aero_sections_;
  std::vector<const BeamStripAero*> aero_strips_;
  std::vector<StripStationInfo> strip_stations_;
  std::vector<const RotorInflow*> aero_rotors_;
  std::vector<std::string> node_names_;  ///< "body <name>" or "beam <name> node <k>", per node
  std::vector<std::string> variable_names_;
  std::vector<bool> driven_;  ///< per variable
  std::vector<std::string> multiplier_names_;
  std::vector<std::string> element_state_names_;  ///< "<owner> <state name>", per element state
  std::vector<double> breakpoints_;
  SolverSpec solver_;
  OutputSpec output_;
  State initial_state_;
  std::string source_;
  double length_scale_ = 1.0;
};

/// Builds and validates a Model. Throws ConfigError for inconsistent input (unknown body names, non-positive
/// mass, initial poses that violate a joint, a drive whose f(0) differs from the initial position), for a
/// model with no body and no beam (nothing to move), and for output larger than CheckOutputSize allows.
Model BuildModel(const ModelSpec& spec);

}  // namespace flexmbd
