#include "variable_effects_builder.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "flexmbd/common/error.hpp"
#include "flexmbd/effects/friction_effect.hpp"
#include "flexmbd/effects/joint_stop.hpp"
#include "flexmbd/effects/variable_effects.hpp"
#include "flexmbd/math/time_function.hpp"
#include "flexmbd/model/effect_validation.hpp"

namespace flexmbd {

void VariableEffectsBuilder::Add(const std::string& where, const JointSpec& joint, int v,
                                 const VariableEffectsSpec& effects, int* multiplier) {
  for (const SpringSpec& s : effects.springs) {
    model_.elements_.push_back(std::make_unique<VariableSpring>(v, model_.variable_unknown(v), s.stiffness, s.rest));
  }
  for (const DamperSpec& d : effects.dampers) {
    model_.elements_.push_back(std::make_unique<VariableDamper>(v, model_.variable_unknown(v), d.coefficient));
  }
  if (effects.drives.size() > 1) throw ConfigError(where + "more than one drive on one variable");
  for (const TimeFunctionSpec& law : effects.drives) AddDrive(where, v, law, multiplier);
  if (effects.static_hold) AddHold(where, v, effects, multiplier);
  for (const StopSpec& stop : effects.stops) AddStop(where, v, stop, multiplier);
  if (effects.frictions.size() > 1) throw ConfigError(where + "more than one friction on one variable");
  // A stuck joint is held by a constraint, which would repeat the drive's and make the iteration matrix singular.
  const bool sticks = !effects.frictions.empty() && effects.frictions[0].law != FrictionSpec::Law::kRegularised;
  if (sticks && !effects.drives.empty()) {
    throw ConfigError(where + "friction that sticks on a driven variable: sticking would hold the motion the drive "
                      "prescribes a second time; expected no friction there (on a driven variable it changes only "
                      "the drive's effort, not the motion) or law: regularised");
  }
  for (const FrictionSpec& friction : effects.frictions) AddFriction(where, joint, v, friction, multiplier);
}

void VariableEffectsBuilder::AddDrive(const std::string& where, int v, const TimeFunctionSpec& law, int* multiplier) {
  const double q0 = Evaluate(law, 0.0);
  const double q_initial = model_.initial_state_.q[v];
  if (std::abs(q0 - q_initial) > kInitialConstraintTolerance) {
    std::ostringstream msg;
    msg << where << "drive starts at " << q0 << " but the initial position is " << q_initial
        << "; expected them equal";
    throw ConfigError(msg.str());
  }
  model_.elements_.push_back(std::make_unique<VariableDrive>(v, model_.variable_unknown(v), *multiplier,
                                                             model_.multiplier_unknown(*multiplier), law));
  model_.multiplier_names_.push_back("drive " + model_.variable_names_[v]);
  model_.driven_[v] = true;
  model_.initial_state_.drive_rates[v] = EvaluateRate(law, 0.0);  // the initial rate (config: initial.velocity)
  ++*multiplier;
}

void VariableEffectsBuilder::AddHold(const std::string& where, int v, const VariableEffectsSpec& effects,
                                    int* multiplier) {
  const SolverSpec& solver = model_.solver();
  // An eigen-analysis's static_first solves the equilibrium it linearises about, of the free system: a hold there
  // would linearise about a state that is not one.
  if (solver.analysis == SolverSpec::Analysis::kEigen) {
    throw ConfigError(where + "initial.static_hold in an eigen-analysis, which linearises about the free system (with "
                      "solver.eigen.static_first: its equilibrium without holds); expected no static_hold here (it "
                      "holds a variable in analysis: static, or in a dynamic run's solver.static_first)");
  }
  if (solver.analysis != SolverSpec::Analysis::kStatic &&
      !(solver.analysis == SolverSpec::Analysis::kDynamic && solver.static_first)) {
    throw ConfigError(where + "initial.static_hold holds the variable in a static analysis, and this run has none; "
                      "expected solver.static_first: true (or analysis: static)");
  }
  if (!effects.drives.empty()) {
    throw ConfigError(where + "initial.static_hold on a driven variable, which its drive holds already; expected "
                      "one of them");
  }
  model_.elements_.push_back(std::make_unique<VariableHold>(v, model_.variable_unknown(v), *multiplier,
                                                            model_.multiplier_unknown(*multiplier),
                                                            model_.initial_state_.q[v]));
  model_.multiplier_names_.push_back("hold " + model_.variable_names_[v]);
  ++*multiplier;
}

std::string VariableEffectsBuilder::PositionText(int v, double q) const {
  const Joint& joint = *model_.joints_.back();
  const std::vector<RotationFactor>& rotations = joint.kinematics().rotations;
  const bool angular = std::any_of(rotations.begin(), rotations.end(), [&](const RotationFactor& factor) {
    return factor.variable == v - joint.first_variable();
  });
  std::ostringstream text;
  if (angular) {
    text << q << " rad (" << q * 180.0 / M_PI << " deg)";
  } else {
    text << q << " m";
  }
  return text.str();
}

void VariableEffectsBuilder::AddStop(const std::string& where, int v, StopSpec stop, int* multiplier) {
  ValidateStop(where, stop);
  if (!stop.retraction.joint.empty()) {
    const auto named = first_variable_of_.find(stop.retraction.joint);
    if (named == first_variable_of_.end()) {
      std::string joints;
      for (const auto& [name, first_variable] : first_variable_of_) joints += (joints.empty() ? "" : ", ") + name;
      throw ConfigError(where + "stop '" + stop.name + "': retract.joint '" + stop.retraction.joint +
                        "' is not a joint of the model; expected one of: " + joints);
    }
    stop.retraction.variable = named->second;
  }
  const int slot = static_cast<int>(model_.modal_effects_.size());
  std::unique_ptr<JointStop> element;
  if (stop.kind == StopSpec::Kind::kRigid) {
    element = std::make_unique<RigidStop>(stop, v, model_.variable_unknown(v), *multiplier,
                                          model_.multiplier_unknown(*multiplier), slot, model_.solver());
    model_.multiplier_names_.push_back("stop " + stop.name + " of " + model_.variable_names_[v]);
    ++*multiplier;
  } else {
    element = std::make_unique<ElasticStop>(stop, v, model_.variable_unknown(v), slot, model_.solver(),
                                            model_.length_scale(), model_.moves_with_algebraic_rotation(v));
  }
  const double q_initial = model_.initial_state_.q[v];
  if (element->Gap(q_initial) < -kInitialConstraintTolerance) {
    throw ConfigError(where + "stop '" + stop.name + "': the initial position " + PositionText(v, q_initial) +
                      " is beyond the stop at " + PositionText(v, stop.limit) +
                      "; expected an initial position inside the stops");
  }
  // Named by its variable, so that stops on two variables of one joint are told apart (joint/k).
  model_.stops_.push_back({model_.variable_names_[v], stop.name, v});
  model_.stop_effects_.push_back(element.get());
  model_.modal_effects_.push_back(element.get());
  model_.elements_.push_back(std::move(element));
}

void VariableEffectsBuilder::LinkImpactStops() {
  for (const auto& element : model_.elements_) {
    auto* friction = dynamic_cast<FrictionEffect*>(element.get());
    if (friction == nullptr) continue;
    std::vector<int> others;
    for (const JointStop* stop : model_.stop_effects_) {
      if (stop->rigid() && stop->variable() != friction->variable()) others.push_back(stop->slot());
    }
    friction->set_impact_stop_slots(std::move(others));
  }
}

void VariableEffectsBuilder::AddFriction(const std::string& where, const JointSpec& joint, int v,
                                         const FrictionSpec& friction, int* multiplier) {
  ValidateFriction(where, friction, joint.type);
  const bool sticks = friction.law != FrictionSpec::Law::kRegularised;
  const int slot = static_cast<int>(model_.modal_effects_.size());
  const Joint& element_joint = *model_.joints_.back();
  auto element = std::make_unique<FrictionEffect>(
      friction, element_joint, model_.variable_unknown(v), sticks ? *multiplier : -1,
      sticks ? model_.multiplier_unknown(*multiplier) : -1,
      model_.multiplier_unknown(element_joint.first_multiplier()), slot, model_.solver());
  std::vector<int> rigid_stops;
  for (const JointStop* stop : model_.stop_effects_) {
    if (stop->variable() == v && stop->rigid()) rigid_stops.push_back(stop->slot());
  }
  element->set_rigid_stop_slots(std::move(rigid_stops));
  for (const auto& other : model_.elements_) {
    auto* stop = dynamic_cast<RigidStop*>(other.get());
    if (stop != nullptr && stop->variable() == v) stop->set_friction(element.get());
  }
  if (sticks) {
    model_.multiplier_names_.push_back("friction " + model_.variable_names_[v]);
    ++*multiplier;
  }
  model_.initial_state_.effects[slot].mode = FrictionEffect::InitialMode(model_.initial_state_.qdot[v]);
  model_.frictions_.push_back({joint.name, v});
  model_.friction_effects_.push_back(element.get());
  model_.modal_effects_.push_back(element.get());
  model_.elements_.push_back(std::move(element));
}

}  // namespace flexmbd
