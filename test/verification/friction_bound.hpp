#pragma once
// The static friction bound on output samples (issue 14): every frictional joint's torque within mu_s rho N.

#include <algorithm>
#include <cmath>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/output_sample.hpp"

namespace flexmbd {
namespace test {

// The law of the model's frictional joint k (model.frictions()[k]) as the spec gives it.
inline const FrictionSpec& FrictionLaw(const ModelSpec& spec, const Model& model, size_t k) {
  const FrictionInfo& info = model.frictions()[k];
  const auto joint = std::find_if(spec.joints.begin(), spec.joints.end(),
                                  [&](const JointSpec& j) { return j.name == info.joint; });
  const auto element = std::find_if(model.joints().begin(), model.joints().end(),
                                    [&](const Joint* j) { return j->name() == info.joint; });
  return joint->effects[info.variable - (*element)->first_variable()].frictions[0];
}

// |torque| / (mu_s rho N) of a Coulomb law with a normal force, 0 for a frictionless one (no torque).
inline double StaticBoundRatio(const FrictionSpec& friction, double torque, double normal_force) {
  return friction.mu_s == 0 ? 0.0 : std::abs(torque) / (friction.mu_s * friction.radius * normal_force);
}

// Largest |friction torque| / (mu_s rho N) over the frictional joints of a sample (Coulomb laws with a
// normal force), 0 without friction.
inline double StaticBoundRatio(const ModelSpec& spec, const Model& model, const OutputSample& sample) {
  double worst = 0;
  for (size_t k = 0; k < model.frictions().size(); ++k) {
    const FrictionSample& f = sample.friction[k];
    worst = std::max(worst, StaticBoundRatio(FrictionLaw(spec, model, k), f.torque, f.normal_force));
  }
  return worst;
}

}  // namespace test
}  // namespace flexmbd
