#include <Eigen/Eigenvalues>
#include <algorithm>
#include <map>
#include <sstream>

#include "flexmbd/common/error.hpp"
#include "flexmbd/elements/applied_load.hpp"
#include "flexmbd/math/time_function.hpp"
#include "flexmbd/model/beam_layout.hpp"
#include "flexmbd/model/eigen_size.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/model/output_size.hpp"
#include "flexmbd/solver/energy_decaying_integrator.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "aero_section_builder.hpp"
#include "aero_strip_builder.hpp"
#include "variable_effects_builder.hpp"

namespace flexmbd {
namespace {
std::string Prefix(const ModelSpec& spec) { return spec.source.empty() ? std::string() : spec.source + ": "; }

void ValidateBody(const ModelSpec& spec, const BodySpec& body) {
  if (!(body.mass > 0.0)) {
    std::ostringstream msg;
    msg << Prefix(spec) << "body '" << body.name << "': mass " << body.mass
        << " is not positive; expected mass > 0 [kg]";
    throw ConfigError(msg.str());
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(0.5 * (body.inertia_cm_B + body.inertia_cm_B.transpose()));
  if (eig.eigenvalues().minCoeff() < 0.0) {
    throw ConfigError(Prefix(spec) + "body '" + body.name +
                      "': inertia tensor is not positive semi-definite; expected principal moments >= 0 [kg m^2]");
  }
}

NodeState NodeFromBody(const BodySpec& body) {
  NodeState n;
  const Vec3 p_BoBcm_W = body.R_WB * body.p_BoBcm_B;
  n.x = body.p_WB + p_BoBcm_W;
  n.R = body.R_WB;
  n.v = body.v_WBo_W + body.w_WB_W.cross(p_BoBcm_W);
  n.w = body.R_WB.transpose() * body.w_WB_W;
  return n;
}

// A lumped mass's own node at its centre of mass p_NC (in the node frame), moving rigidly with the beam node.
NodeState OffsetNode(const NodeState& beam_node, const Vec3& p_NC) {
  NodeState n = beam_node;
  const Vec3 r = beam_node.R * p_NC;
  n.x += r;
  n.v += (beam_node.R * beam_node.w).cross(r);
  return n;
}

// A lumped beam mass off the beam axis: its node, the beam node that holds it and its offset there.
struct OffsetMass {
  std::string name;
  int beam_node = -1, mass_node = -1;
  Vec3 p_NC = Vec3::Zero();
};

// The stations of output.beam_stations on their elements; throws ConfigError for an unknown beam or a station
// off the beam.
std::vector<BeamStationInfo> LocateBeamStations(const ModelSpec& spec, const std::vector<BeamInfo>& beams) {
  std::vector<BeamStationInfo> located;
  for (const auto& [name, stations] : spec.output.beam_stations) {
    const std::string field = Prefix(spec) + "output.beam_stations." + name;
    size_t b = 0;
    while (b < beams.size() && beams[b].name != name) ++b;
    if (b == beams.size()) throw ConfigError(field + ": no beam '" + name + "'; expected the name of a beam (beams:)");
    const BeamSpec& beam = spec.beams[b];
    for (size_t k = 0; k < stations.size(); ++k) {
      if (!(stations[k] >= 0.0 && stations[k] <= beam.length)) {
        std::ostringstream msg;
        msg << field << "[" << k << "]: " << stations[k] << " is off the beam; expected 0 <= s <= " << beam.length
            << " [m] (distance from the root)";
        throw ConfigError(msg.str());
      }
      const ElementPoint p = LocateOnBeam(beam, stations[k]);
      located.push_back({name, static_cast<int>(k), stations[k], beams[b].elements[p.element], p.s});
    }
  }
  return located;
}
// The breakpoints of every time function of the model, increasing, each once (Model::breakpoints).
std::vector<double> TimeFunctionBreakpoints(const ModelSpec& spec) {
  std::vector<double> all;
  auto add = [&all](const TimeFunctionSpec& f) {
    const std::vector<double> own = Breakpoints(f);
    all.insert(all.end(), own.begin(), own.end());
  };
  for (const JointSpec& joint : spec.joints) {
    for (const VariableEffectsSpec& effects : joint.effects) {
      for (const TimeFunctionSpec& drive : effects.drives) add(drive);
    }
  }
  for (const LoadSpec& load : spec.loads) add(load.scale);
  add(spec.aero_flow.gust_scale);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

}  // namespace

std::string Model::DescribeUnknown(int unknown) const {
  static const char* kNodeDof[6] = {"x", "y", "z", "rot_x", "rot_y", "rot_z"};
  if (unknown < 6 * num_nodes_) return node_names_[unknown / 6] + " " + kNodeDof[unknown % 6];
  if (unknown < 6 * num_nodes_ + num_variables_) return "joint variable " + variable_names_[unknown - 6 * num_nodes_];
  if (unknown < num_kinematic()) return element_state_names_[unknown - 6 * num_nodes_ - num_variables_];
  return multiplier_names_[unknown - num_kinematic()];
}

int Model::FindVariable(const std::string& name) const {
  const auto found = std::find(variable_names_.begin(), variable_names_.end(), name);
  return found == variable_names_.end() ? -1 : static_cast<int>(found - variable_names_.begin());
}

Model BuildModel(const ModelSpec& spec) {
  if (spec.bodies.empty() && spec.beams.empty()) {
    throw ConfigError(Prefix(spec) + "nothing can move: the model has no body and no beam; expected at least one");
  }
  const SolverSpec& solver = spec.solver;
  if (solver.integrator == SolverSpec::Integrator::kEnergyDecaying &&
      !(solver.rho_inf >= kMinRhoInf && solver.rho_inf <= 1.0)) {
    std::ostringstream msg;
    msg << Prefix(spec) << "solver.rho_inf: " << solver.rho_inf
        << " is outside the range of the energy-decaying scheme; expected 1/3 <= rho_inf <= 1";
    throw ConfigError(msg.str());
  }
  Model model;
  model.source_ = spec.source;
  model.solver_ = spec.solver;
  model.output_ = spec.output;
  model.breakpoints_ = TimeFunctionBreakpoints(spec);
  std::map<std::string, int> body_index;
  for (const BodySpec& body : spec.bodies) {
    ValidateBody(spec, body);
    if (!body_index.emplace(body.name, static_cast<int>(model.bodies_.size())).second) {
      throw ConfigError(Prefix(spec) + "body '" + body.name + "' is defined twice");
    }
    const int node = model.num_nodes_++;
    model.bodies_.push_back({body.name, node, -body.p_BoBcm_B});
    model.initial_state_.nodes.push_back(NodeFromBody(body));
    model.length_scale_ = std::max(model.length_scale_, model.initial_state_.nodes.back().x.norm());
  }
  for (const BodySpec& body : spec.bodies) {
    const int node = body_index.at(body.name);
    auto rigid = std::make_unique<RigidBody>(node, model.node_unknown(node), body.mass, body.inertia_cm_B);
    model.rigid_bodies_.push_back(rigid.get());
    model.elements_.push_back(std::move(rigid));
    model.node_names_.push_back("body " + body.name);
  }

  // Beams: nodes along the link's x axis, lumped masses on them, elements between them.
  std::map<std::string, int> beam_index;
  std::vector<OffsetMass> offset_masses;
  for (const BeamSpec& beam : spec.beams) {
    ValidateBeam(Prefix(spec), beam);
    if (body_index.count(beam.name) || !beam_index.emplace(beam.name, static_cast<int>(model.beams_.size())).second) {
      throw ConfigError(Prefix(spec) + "beams." + beam.name + ": the link is defined twice");
    }
    BeamInfo info;
    info.name = beam.name;
    info.stations = BeamStations(beam);
    info.lumped_lengths = LumpedLengths(beam);
    info.damping = beam.damping;
    const std::vector<NodeState> nodes = BeamNodeStates(beam);
    // With a centre-of-mass offset each lumped mass is a rigid body of its own, at its centre of mass, held on
    // the beam node by a fixed joint (theory (B6)).
    const Vec3 p_NC(0.0, beam.section.cg_offset.x(), beam.section.cg_offset.y());
    for (size_t k = 0; k < nodes.size(); ++k) {
      const int node = model.num_nodes_++;
      info.nodes.push_back(node);
      model.initial_state_.nodes.push_back(nodes[k]);
      model.length_scale_ = std::max(model.length_scale_, nodes[k].x.norm());
      const std::string node_name = "beam " + beam.name + " node " + std::to_string(k);
      model.node_names_.push_back(node_name);
      int mass_node = node;
      if (!p_NC.isZero()) {
        mass_node = model.num_nodes_++;
        model.initial_state_.nodes.push_back(OffsetNode(nodes[k], p_NC));
        model.node_names_.push_back(node_name + " centre of mass");
        offset_masses.push_back({node_name + " centre of mass", node, mass_node, p_NC});
        model.num_multipliers_ += 6;
      }
      const double lumped = info.lumped_lengths[k];
      const Mat3 inertia = lumped * beam.section.inertia_per_length.asDiagonal().toDenseMatrix();
      auto mass = std::make_unique<RigidBody>(mass_node, model.node_unknown(mass_node),
                                              lumped * beam.section.mass_per_length, inertia);
      model.rigid_bodies_.push_back(mass.get());
      model.elements_.push_back(std::move(mass));
    }
    const Eigen::Matrix<double, 6, 6> stiffness = BeamSectionStiffness(beam.section);
    for (int e = 0; e < beam.elements; ++e) {
      const std::vector<int> element_nodes(info.nodes.begin() + e * beam.order,
                                           info.nodes.begin() + (e + 1) * beam.order + 1);
      auto element = std::make_unique<BeamElement>(beam.name + " element " + std::to_string(e), element_nodes,
                                                   beam.length / beam.elements, stiffness, beam.damping);
      info.elements.push_back(element.get());
      model.elements_.push_back(std::move(element));
    }
    model.beams_.push_back(info);
  }
  model.beam_stations_ = LocateBeamStations(spec, model.beams_);
  model.node_beams_.assign(model.num_nodes_, -1);
  for (size_t b = 0; b < model.beams_.size(); ++b) {
    for (int node : model.beams_[b].nodes) model.node_beams_[node] = static_cast<int>(b);
  }
  // A beam node's rotation is algebraic where nothing gives it inertia: no m_ii on its own lumped mass, no lumped mass
  // off the axis (whose m |c|^2 is rotary inertia about the node).
  model.algebraic_rotations_.assign(model.num_nodes_, false);
  for (const RigidBody* body : model.rigid_bodies_) {
    model.algebraic_rotations_[body->node()] = model.node_beams_[body->node()] >= 0 && body->inertia().isZero(0.0);
  }
  for (const OffsetMass& offset : offset_masses) model.algebraic_rotations_[offset.beam_node] = false;

  // The node a link-frame point belongs to, and the point relative to that node (node frame).
  auto locate = [&](const std::string& what, const std::string& link, const Vec3& p_B, int* node, Vec3* p_N) {
    const auto body = body_index.find(link);
    if (body != body_index.end()) {
      *node = model.bodies_[body->second].node;
      *p_N = p_B + model.bodies_[body->second].p_NBo_N;
      return;
    }
    const auto beam = beam_index.find(link);
    if (beam == beam_index.end()) throw ConfigError(Prefix(spec) + what + ": no body or beam '" + link + "'");
    const BeamInfo& info = model.beams_[beam->second];
    const int k = StationAt(info.stations, p_B.x(), info.stations.back());
    if (k < 0) throw ConfigError(Prefix(spec) + what + ": " + OffNodeText(spec.beams[beam->second], p_B.x()));
    *node = info.nodes[k];
    *p_N = Vec3(0.0, p_B.y(), p_B.z());
  };

  auto attachment = [&](const std::string& joint, const std::string& link, const Vec3& p_BJ, const Mat3& R_BJ) {
    Joint::Attachment side;
    side.R_NJ = R_BJ;
    side.p_NJ = p_BJ;
    if (link.empty()) return side;
    locate("joint '" + joint + "'", link, p_BJ, &side.node, &side.p_NJ);
    side.first_unknown = model.node_unknown(side.node);
    return side;
  };

  // Count unknowns first: element constructors need the final global indices.
  std::map<std::string, int> first_variable_of;
  int num_effect_slots = 0;
  for (const JointSpec& joint : spec.joints) {
    first_variable_of[joint.name] = model.num_variables_;
    if (joint.effects.size() > static_cast<size_t>(NumJointVariables(joint.type))) {
      throw ConfigError(Prefix(spec) + "joint '" + joint.name + "': effects given for " +
                        std::to_string(joint.effects.size()) + " variables but a " + JointTypeName(joint.type) +
                        " joint has " + std::to_string(NumJointVariables(joint.type)));
    }
    model.num_variables_ += NumJointVariables(joint.type);
    model.num_multipliers_ += (joint.type == JointType::kSpherical ? 3 : 6);
    for (const VariableEffectsSpec& effects : joint.effects) {
      model.num_multipliers_ += effects.drives.size() + effects.static_hold;
      for (const StopSpec& stop : effects.stops) model.num_multipliers_ += stop.kind == StopSpec::Kind::kRigid;
      for (const FrictionSpec& f : effects.frictions) {
        model.num_multipliers_ += f.law != FrictionSpec::Law::kRegularised;
      }
      num_effect_slots += effects.stops.size() + effects.frictions.size();
    }
  }
  if (num_effect_slots > 0 && solver.integrator == SolverSpec::Integrator::kGeneralizedAlpha) {
    throw ConfigError(Prefix(spec) + "solver.integrator: generalized_alpha does not support stops or friction; "
                      "expected energy_decaying or energy_preserving");
  }
  for (const AeroSectionSpec& section : spec.aero_sections) model.num_element_states_ += section.inflow_states;
  for (const AeroStripSpec& strip : spec.aero_strips) {
    model.num_element_states_ += strip.inflow_states * StripBeam(model, Prefix(spec), strip).nodes.size();
  }
  // The rotors' inflows follow the strips' states (their strips need the inflows' unknowns).
  const int first_rotor_state = model.num_element_states_;
  for (const AeroRotorSpec& rotor : spec.aero_rotors) model.num_element_states_ += RotorInflowStates(rotor);
  for (const CustomElementSpec& custom : spec.custom_elements) model.num_element_states_ += custom.num_states;
  State& state = model.initial_state_;
  state.element_states = Eigen::VectorXd::Zero(model.num_element_states_);
  state.element_state_rates = Eigen::VectorXd::Zero(model.num_element_states_);
  state.element_state_rates_alg = Eigen::VectorXd::Zero(model.num_element_states_);
  state.peak_state_rate = Eigen::VectorXd::Zero(model.num_element_states_);
  state.q = Eigen::VectorXd::Zero(model.num_variables_);
  state.qdot = Eigen::VectorXd::Zero(model.num_variables_);
  state.peak_joint_rate = Eigen::VectorXd::Zero(model.num_variables_);
  state.lambda = Eigen::VectorXd::Zero(model.num_multipliers_);
  state.effects.resize(num_effect_slots);
  state.commands.resize(model.num_variables_);
  state.drive_rates = Eigen::VectorXd::Zero(model.num_variables_);
  model.driven_.assign(model.num_variables_, false);
  model.on_algebraic_rotations_.assign(model.num_variables_, false);

  int variable = 0, multiplier = 0;
  VariableEffectsBuilder effect_builder(&model, first_variable_of);
  for (const JointSpec& joint : spec.joints) {
    if (joint.child.empty()) throw ConfigError(Prefix(spec) + "joint '" + joint.name + "': child body is missing");
    const JointKinematics kinematics = MakeJointKinematics(joint);
    const int n_var = kinematics.num_variables;
    auto element = std::make_unique<Joint>(
        joint.name, attachment(joint.name, joint.parent, joint.p_PJ, joint.R_PJ),
        attachment(joint.name, joint.child, joint.p_CJ, joint.R_CJ), kinematics, variable,
        model.variable_unknown(variable), multiplier, model.multiplier_unknown(multiplier));
    const int n_con = element->num_constraints();
    bool on_algebraic = false;
    for (const Joint::Attachment* side : {&element->parent(), &element->child()}) {
      on_algebraic = on_algebraic || (side->node >= 0 && model.algebraic_rotations_[side->node]);
    }
    for (int k = 0; k < n_var; ++k) model.on_algebraic_rotations_[variable + k] = on_algebraic;
    model.joints_.push_back(element.get());
    model.elements_.push_back(std::move(element));
    for (int c = 0; c < n_con; ++c) {
      model.multiplier_names_.push_back("joint " + joint.name + " constraint " + std::to_string(c));
    }
    multiplier += n_con;
    for (int k = 0; k < n_var; ++k) {
      const int v = variable + k;
      model.variable_names_.push_back(n_var == 1 ? joint.name : joint.name + "/" + std::to_string(k));
      if (k < static_cast<int>(joint.initial_position.size())) state.q[v] = joint.initial_position[k];
      if (k < static_cast<int>(joint.initial_velocity.size())) state.qdot[v] = joint.initial_velocity[k];
      model.elements_.push_back(std::make_unique<VariableEffort>(v, model.variable_unknown(v)));
      if (k >= static_cast<int>(joint.effects.size())) continue;  // no effects on this variable
      // named by the variable (joint/k of a multi-variable joint), as joint_states names it
      effect_builder.Add(Prefix(spec) + "joint '" + model.variable_names_.back() + "': ", joint, v, joint.effects[k],
                         &multiplier);
    }
    variable += n_var;
  }
  effect_builder.LinkImpactStops();

  for (const OffsetMass& offset : offset_masses) {
    JointSpec fixed;
    fixed.type = JointType::kFixed;
    Joint::Attachment holder, mass;
    holder.node = offset.beam_node;
    holder.first_unknown = model.node_unknown(offset.beam_node);
    holder.p_NJ = offset.p_NC;
    mass.node = offset.mass_node;
    mass.first_unknown = model.node_unknown(offset.mass_node);
    model.elements_.push_back(std::make_unique<Joint>(offset.name, holder, mass, MakeJointKinematics(fixed), variable,
                                                      model.variable_unknown(variable), multiplier,
                                                      model.multiplier_unknown(multiplier)));
    for (int c = 0; c < 6; ++c) model.multiplier_names_.push_back(offset.name + " constraint " + std::to_string(c));
    multiplier += 6;
  }

  for (const LoadSpec& load : spec.loads) {
    if (load.distributed) {
      const auto beam = beam_index.find(load.body);
      if (beam == beam_index.end()) {
        throw ConfigError(Prefix(spec) + "load on '" + load.body + "': '" + load.body +
                          "' is not a beam; expected a distributed load on a link under beams:");
      }
      const BeamInfo& info = model.beams_[beam->second];
      const std::vector<LoadSpec> nodal = NodalLoads(load, info.lumped_lengths);
      for (size_t k = 0; k < nodal.size(); ++k) {
        model.elements_.push_back(
            std::make_unique<AppliedLoad>(info.nodes[k], model.node_unknown(info.nodes[k]), nodal[k], Vec3::Zero()));
      }
      continue;
    }
    int node = -1;
    Vec3 p_NP;
    locate("load on '" + load.body + "'", load.body, load.p_BoP_B, &node, &p_NP);
    model.elements_.push_back(std::make_unique<AppliedLoad>(node, model.node_unknown(node), load, p_NP));
  }

  int first_state = 0;
  auto add_state_owner = [&](std::unique_ptr<Element> element) {
    element->set_first_state(first_state);
    for (int k = 0; k < element->num_states(); ++k) {
      model.element_state_names_.push_back(element->StateOwnerName() + " " + element->StateName(k));
    }
    first_state += element->num_states();
    model.elements_.push_back(std::move(element));
  };
  for (const AeroSectionSpec& section : spec.aero_sections) {
    auto element = MakeAeroSection(model, Prefix(spec), section, first_state);
    model.aero_sections_.push_back(element.get());
    add_state_owner(std::move(element));
  }
  const std::vector<StripRotor> strip_rotors = StripRotors(model, Prefix(spec), spec, first_rotor_state);
  std::vector<std::vector<const BeamStripAero*>> blades(spec.aero_rotors.size());
  for (size_t k = 0; k < spec.aero_strips.size(); ++k) {
    const StripRotor& rotor = strip_rotors[k];
    for (auto& element : MakeAeroStrips(model, Prefix(spec), spec.aero_strips[k], spec.aero_flow, first_state, rotor)) {
      model.aero_strips_.push_back(element.get());
      if (rotor.index >= 0) blades[rotor.index].push_back(element.get());
      add_state_owner(std::move(element));
    }
  }
  FLEXMBD_DEMAND(first_state == first_rotor_state);
  for (size_t r = 0; r < spec.aero_rotors.size(); ++r) {
    auto element = std::make_unique<RotorInflow>(spec.aero_rotors[r], spec.aero_flow,
                                                 model.element_state_unknown(first_state));
    element->set_strips(blades[r]);
    model.aero_rotors_.push_back(element.get());
    add_state_owner(std::move(element));
  }
  model.strip_stations_ = LocateStripStations(model, Prefix(spec), spec);
  for (const CustomElementSpec& custom : spec.custom_elements) {
    std::unique_ptr<Element> element = custom.make(model, first_state);
    FLEXMBD_DEMAND(element->num_states() == custom.num_states);
    add_state_owner(std::move(element));
  }
  FLEXMBD_DEMAND(first_state == model.num_element_states_);

  model.initial_state_.element_history.resize(model.elements_.size());
  for (size_t k = 0; k < model.elements_.size(); ++k) {
    model.elements_[k]->set_index(static_cast<int>(k));
    model.initial_state_.element_history[k] = Eigen::VectorXd::Zero(model.elements_[k]->history_size());
  }

  // The initial poses must satisfy every joint.
  StepContextBuilder context(model);
  const StepContext ctx = context.AtState(state);
  for (const Joint* joint : model.joints_) {
    const double violation = joint->ConstraintValues(ctx).cwiseAbs().maxCoeff();
    if (violation > kInitialConstraintTolerance) {
      std::ostringstream msg;
      msg << Prefix(spec) << "joint '" << joint->name() << "': initial poses violate the joint by " << violation
          << "; expected body poses consistent with the joint's initial position";
      throw ConfigError(msg.str());
    }
  }
  CheckOutputSize(model);
  CheckEigenSize(model);
  CheckSparseEigenStates(model);
  return model;
}

}  // namespace flexmbd
