#pragma once
// The static friction bound on output samples (issue 14): every frictional joint's torque within mu_s rho N.

#include <algorithm>
#include <cmath>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/output_sample.hpp"

namespace flexmbd {
namespace test {

// Largest |friction torque| / (mu_s rho N) over the frictional joints of a sample (Coulomb laws with a
// normal force), 0 without friction.
inline double StaticBoundRatio(const ModelSpec& spec, const Model& model, const OutputSample& sample) {
  double worst = 0;
  for (size_t k = 0; k < model.frictions().size(); ++k) {
    const FrictionInfo& info = model.frictions()[k];
    const auto joint = std::find_if(spec.joints.begin(), spec.joints.end(),
                                    [&](const JointSpec& j) { return j.name == info.joint; });
    const auto element = std::find_if(model.joints().begin(), model.joints().end(),
                                      [&](const Joint* j) { return j->name() == info.joint; });
    const FrictionSpec& friction = joint->effects[info.variable - (*element)->first_variable()].frictions[0];
    if (friction.mu_s == 0) continue;  // frictionless: no torque
    const FrictionSample& f = sample.friction[k];
    worst = std::max(worst, std::abs(f.torque) / (friction.mu_s * friction.radius * f.normal_force));
  }
  return worst;
}

}  // namespace test
}  // namespace flexmbd
