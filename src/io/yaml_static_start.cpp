// A run that starts from its static equilibrium starts at rest: an initial joint velocity given with it is refused.

#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {

void CheckStaticStart(const Field& root, const ModelSpec& spec) {
  const SolverSpec& solver = spec.solver;
  const bool dynamic = solver.analysis == SolverSpec::Analysis::kDynamic && solver.static_first;
  const bool eigen = solver.analysis == SolverSpec::Analysis::kEigen && solver.eigen.static_first;
  if (!dynamic && !eigen) return;
  const std::string flag = dynamic ? "solver.static_first" : "solver.eigen.static_first";
  for (const JointSpec& joint : spec.joints) {
    const Field field = root.Child("joints").Child(joint.name);
    for (size_t v = 0; v < joint.velocity_set.size(); ++v) {
      // A driven variable's velocity is its drive's f'(0), not a choice of the user's.
      if (!joint.velocity_set[v] || joint.initial_velocity[v] == 0.0 || !joint.effects[v].drives.empty()) continue;
      const Field initial = v == 0 && field.Child("initial").present()
                                ? field.Child("initial")
                                : field.Child("variables").Entry(v).Child("initial");
      const Field given =
          initial.Child("velocity").present() ? initial.Child("velocity") : initial.Child("velocity_deg");
      given.Fail(given.Text() + " with " + flag + ": true, which starts from the static equilibrium at rest and "
                 "would discard it; expected no initial velocity, or static_first: false to start from the given "
                 "position and velocity");
    }
  }
}

}  // namespace io
}  // namespace flexmbd
