#pragma once
/// @file
/// Internal to BuildModel: the effects on one joint variable (springs, dampers, a drive, stops, a friction)
/// as elements of the Model, with the multipliers, names and effect slots they add, each checked against the
/// initial state.

#include <map>
#include <string>

#include "flexmbd/model/model.hpp"

namespace flexmbd {

/// Initial configurations must satisfy the joints, drives and stops to this accuracy [m or rad]: loader
/// forward kinematics is exact to round-off, so anything larger is an inconsistent input.
inline constexpr double kInitialConstraintTolerance = 1.0e-8;

class VariableEffectsBuilder {
 public:
  /// `first_variable_of` maps each joint's name to its first variable (a stop's retraction names a joint);
  /// both must outlive the builder.
  VariableEffectsBuilder(Model* model, const std::map<std::string, int>& first_variable_of)
      : model_(*model), first_variable_of_(first_variable_of) {}

  /// Adds `effects`, those of variable `v` of `joint`, whose element is the last of the model's joints so far.
  /// `*multiplier` is the next free multiplier and is advanced past those the effects add. `where` begins
  /// every ConfigError ("<source>: joint 'NAME': ").
  void Add(const std::string& where, const JointSpec& joint, int v, const VariableEffectsSpec& effects,
           int* multiplier);

  /// After every joint's effects: tells each friction the rigid stops on the other variables, whose impacts can turn
  /// its joint's slip within any step (FrictionEffect::set_impact_stop_slots).
  void LinkImpactStops();

 private:
  void AddDrive(const std::string& where, int v, const TimeFunctionSpec& law, int* multiplier);
  void AddHold(const std::string& where, int v, const VariableEffectsSpec& effects, int* multiplier);
  void AddStop(const std::string& where, int v, StopSpec stop, int* multiplier);
  /// A position of variable v of the last joint built, with its unit ("0.5236 rad (30 deg)", "0.2 m").
  std::string PositionText(int v, double q) const;
  void AddFriction(const std::string& where, const JointSpec& joint, int v, const FrictionSpec& friction,
                   int* multiplier);

  Model& model_;
  const std::map<std::string, int>& first_variable_of_;
};

}  // namespace flexmbd
