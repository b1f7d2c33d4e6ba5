#pragma once
/// @file
/// Checks of effect settings that BuildModel applies to any ModelSpec (the YAML reader checks the same with
/// file and field names first). Each throws ConfigError naming the joint and the expected form.

#include <string>

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

/// Radius, stiffness, exponent, restitution, steps per contact and the retraction thresholds of a stop.
void ValidateStop(const std::string& where, const StopSpec& stop);

/// Coefficients (mu_s >= mu_k >= 0), radius > 0, preload >= 0, v0 >= 0 (> 0 for the regularised law), torque
/// >= 0, and the joint type (revolute or prismatic).
void ValidateFriction(const std::string& where, const FrictionSpec& friction, JointType type);

}  // namespace flexmbd
