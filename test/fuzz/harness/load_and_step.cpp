#include "load_and_step.hpp"

#include <algorithm>
#include <typeinfo>

#include "flexmbd/common/error.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/io/yaml_document.hpp"
#include "flexmbd/ros/node_settings.hpp"
#include "flexmbd/ros/param_tree.hpp"
#include "flexmbd/ros/transform_frames.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"
#include "flexmbd/solver/steady_rotation.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "isolated_run.hpp"
#include "param_tree_from_yaml.hpp"

namespace flexmbd {
namespace fuzz {
namespace {

// LoadModelSpec without the file reads; or the node's path: parameter tree -> YAML -> the same loader.
ModelSpec Load(const FuzzInput& input) {
  const YAML::Node params = input.yaml.empty() ? YAML::Node() : io::ParseYamlDocument(input.yaml, kYamlFileName);
  if (input.channel == Channel::kFiles) {
    return LoadModelSpecFromStrings(input.urdf, kUrdfFileName, params, input.yaml.empty() ? "" : kYamlFileName);
  }
  const YAML::Node tree =
      ros::ToYamlWithout(ParamTreeFromYaml(params), kParamNamespace, ros::NodeSettingNames());
  return LoadModelSpecFromStrings(input.urdf, kUrdfParamName, tree, kParamNamespace);
}

void Run(const FuzzInput& input) {
  const Model model = BuildModel(Load(input));
  if (input.channel == Channel::kParamTree) ros::UrdfFrameTree(input.urdf, model);
  if (model.num_unknowns() > kLargestRunModel) return;
  ExtendTimeLimit(TimeLimitFactor(model.num_unknowns()));  // the child's limit, for the model's size
  const auto no_output = [](const OutputSample&) {};
  switch (model.solver().analysis) {
    case SolverSpec::Analysis::kEigen: {
      EigenOptions options;
      options.num_modes = model.solver().eigen.modes;
      options.shift_hz = model.solver().eigen.shift_hz;
      if (model.solver().eigen.about == SolverSpec::EigenSettings::About::kSteadyState) {
        const SteadyRotation spin = SteadyRotationOf(model, model.initial_state());
        const SteadyResult steady = SolveSteadyRotation(model, model.initial_state(), spin);
        EigenAnalysisAboutSteadyRotation(model, steady.state, spin, options);
        return;
      }
      EigenAnalysis(model, model.initial_state(), options);
      return;
    }
    case SolverSpec::Analysis::kStatic:
      Simulation(model).Run(no_output);
      return;
    case SolverSpec::Analysis::kDynamic: {
      Simulation simulation(model);
      if (model.solver().static_first) simulation.SolveStaticStart();
      simulation.Integrate(std::min(model.solver().t_end, kStepsRun * model.solver().dt), no_output);
      return;
    }
  }
}

}  // namespace

unsigned TimeLimitFactor(int unknowns) { return static_cast<unsigned>(std::max(1, unknowns / kUnknownsPerTimeLimit)); }

TargetResult LoadAndStep(const FuzzInput& input) {
  try {
    Run(input);
    return TargetResult{Outcome::kCompleted, ""};
  } catch (const ConfigError& e) {
    return TargetResult{Outcome::kConfigError, e.what()};
  } catch (const SolverError& e) {
    return TargetResult{Outcome::kSolverError, e.what()};
  } catch (const std::exception& e) {
    return TargetResult{Outcome::kOtherException, std::string(typeid(e).name()) + ": " + e.what()};
  } catch (...) {
    return TargetResult{Outcome::kOtherException, "an exception not derived from std::exception"};
  }
}

}  // namespace fuzz
}  // namespace flexmbd
