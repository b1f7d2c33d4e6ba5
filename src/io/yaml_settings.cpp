#include <algorithm>

#include "flexmbd/io/message_text.hpp"
#include "flexmbd/io/output_path.hpp"
#include "flexmbd/io/yaml_sections.hpp"

namespace flexmbd {
namespace io {
namespace {
const std::vector<std::string> kSolverKeys = {
    "analysis",  "integrator",  "rho_inf",        "t_end",      "dt",           "dt_min",  "dt_max", "adaptive", "tol",
    "error_tol", "error_floor", "max_iterations", "load_steps", "static_first", "gravity", "eigen",  "threads"};
// Counts beyond these are typing errors that would run for hours (a fuzzed load_steps of 2e9): each load step is a
// whole Newton solve, and 10,000 already follow a load path in steps of 1e-4 of the load; a Newton solve that
// refreshes its tangent whenever it stops contracting fast converges in tens of iterations or not at all.
constexpr int kMaxLoadSteps = 10000;
constexpr int kMaxNewtonIterations = 1000;
// More threads than this is a typing error: each is started and kept for the run.
constexpr int kMaxThreads = 256;
const std::vector<std::string> kEigenKeys = {"modes", "static_first", "method", "shift_hz", "about", "sweep",
                                             "at_times"};
const std::vector<std::string> kSweepKeys = {"velocity_scale", "airspeed"};
const std::vector<std::string> kErrorFloorKeys = {"position", "rotation", "joint"};
const std::vector<std::string> kOutputKeys = {"rate_hz", "csv", "bag", "beam_stations", "strip_stations",
                                              "allow_large_output", "cycle_from"};

// "0.01", or "0.01 (default)" if the key was not given.
std::string ValueText(const Field& map, const std::string& key, double value) {
  return FormatNumber(value) + (map.Child(key).present() ? "" : " (default)");
}

void CheckStepBounds(const Field& solver, const SolverSpec& spec) {
  const std::string range = "; expected dt_min <= dt <= dt_max [s]";
  if (spec.dt_max < spec.dt_min) {
    solver.Child("dt_max").Fail(ValueText(solver, "dt_max", spec.dt_max) + " is less than dt_min " +
                                ValueText(solver, "dt_min", spec.dt_min) + range);
  }
  if (spec.dt > spec.dt_max) {
    solver.Child("dt").Fail(ValueText(solver, "dt", spec.dt) + " is greater than dt_max " +
                            ValueText(solver, "dt_max", spec.dt_max) + range);
  }
  if (spec.dt < spec.dt_min) {
    solver.Child("dt").Fail(ValueText(solver, "dt", spec.dt) + " is less than dt_min " +
                            ValueText(solver, "dt_min", spec.dt_min) + range);
  }
}

// `solver.eigen.sweep.airspeed:` free-stream speeds in increasing order, so that neighbouring speeds bracket a
// change of stability.
void ReadAirspeedSweep(const Field& list, SolverSpec::EigenSettings* spec) {
  // Positive: Peters' states decay at U/b, and at rest nothing fixes them.
  spec->sweep_airspeed = ReadNumberList(list, Quantity{"a free-stream speed", Bound::kPositive, "m/s"});
  if (spec->sweep_airspeed.empty()) list.Fail("an empty list; expected at least one free-stream speed [m/s]");
  for (size_t k = 1; k < spec->sweep_airspeed.size(); ++k) {
    if (!(spec->sweep_airspeed[k] > spec->sweep_airspeed[k - 1])) {
      list.Entry(k).Fail(list.Entry(k).Text() + " does not exceed the speed before it, " + list.Entry(k - 1).Text() +
                         "; expected speeds in increasing order [m/s]");
    }
  }
}

// `solver.eigen:` the eigen-analysis settings (docs/config.md, "solver.eigen").
void ReadEigen(const Field& eigen, SolverSpec::EigenSettings* spec) {
  using Method = SolverSpec::EigenSettings::Method;
  using About = SolverSpec::EigenSettings::About;
  CheckKeys(eigen, kEigenKeys);
  OverlayInteger(eigen, "modes", Quantity{"a number of modes (0: all)", Bound::kNonNegative, ""}, &spec->modes);
  OverlayBool(eigen, "static_first", &spec->static_first);
  if (eigen.Child("method").present()) {
    spec->method = ReadEnum<Method>(eigen.Child("method"), "eigen method",
                                    {{"auto", Method::kAuto}, {"dense", Method::kDense}, {"sparse", Method::kSparse}});
  }
  OverlayNumber(eigen, "shift_hz", Quantity{"a target frequency", Bound::kNonNegative, "Hz"}, &spec->shift_hz);
  if (spec->method == Method::kDense && spec->shift_hz > 0) {
    eigen.Child("shift_hz").Fail(eigen.Child("shift_hz").Text() + " picks the modes nearest it for the sparse method, "
                                 "and method: dense finds every mode; expected no shift_hz with method: dense (or "
                                 "method: sparse)");
  }
  if (eigen.Child("about").present()) {
    spec->about = ReadEnum<About>(eigen.Child("about"), "state to linearise about",
                                  {{"initial_state", About::kInitialState}, {"steady_state", About::kSteadyState}});
  }
  if (spec->about == About::kSteadyState && spec->static_first) {
    eigen.Child("static_first").Fail("true cannot go with about: steady_state (the steady state includes gravity "
                                     "and loads); expected false");
  }
  if (eigen.Child("at_times").present()) {
    spec->at_times = ReadNumberList(eigen.Child("at_times"), Quantity{"a time", Bound::kNonNegative, "s"});
  }
  const Field sweep = eigen.Child("sweep");
  if (!sweep.present()) return;
  CheckKeys(sweep, kSweepKeys);
  if (sweep.Child("velocity_scale").present() == sweep.Child("airspeed").present()) {
    sweep.Fail("expected exactly one of velocity_scale (factors on the initial velocities, e.g. [0.0, 0.5, 1.0]) "
               "and airspeed (free-stream speeds of the aero sections [m/s], e.g. [10, 20, 30])");
  }
  if (sweep.Child("airspeed").present()) {
    ReadAirspeedSweep(sweep.Child("airspeed"), spec);
    if (spec->about == About::kSteadyState) {
      eigen.Child("about").Fail("steady_state cannot go with an airspeed sweep (linearised about the initial state "
                                "or its static aeroelastic equilibrium); expected initial_state");
    }
    return;
  }
  spec->sweep_velocity_scale =
      ReadNumberList(sweep.Child("velocity_scale"), Quantity{"a velocity factor", Bound::kAny, ""});
  if (spec->sweep_velocity_scale.empty()) {
    sweep.Child("velocity_scale").Fail("an empty list; expected at least one velocity factor");
  }
  if (spec->static_first) {
    eigen.Child("static_first").Fail(
        "true cannot go with a sweep of velocities (the static solution is at rest); expected false");
  }
}

// `solver.eigen.at_times`: the times of a dynamic run whose state is analysed. Checked once the analysis, the
// end time and the rest of solver.eigen are known.
void CheckEigenTimes(const Field& solver, const SolverSpec& spec) {
  const Field eigen = solver.Child("eigen");
  const Field times = eigen.Child("at_times");
  if (!times.present()) return;
  if (spec.analysis != SolverSpec::Analysis::kDynamic) {
    times.Fail("applies to analysis: dynamic (the modes about the state at times of the run); expected no at_times "
               "with another analysis");
  }
  for (const char* key : {"about", "sweep", "static_first"}) {
    if (eigen.Child(key).present()) {
      eigen.Child(key).Fail(std::string("cannot go with at_times (the state analysed is the run's); expected no ") +
                            key);
    }
  }
  const std::vector<double>& t = spec.eigen.at_times;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] > spec.t_end) {
      times.Entry(i).Fail(times.Entry(i).Text() + " s is after solver.t_end " + FormatNumber(spec.t_end) +
                          " s; expected times in [0, t_end]");
    }
    if (i > 0 && !(t[i] > t[i - 1])) {
      times.Entry(i).Fail(times.Entry(i).Text() + " s is not after the previous time " + FormatNumber(t[i - 1]) +
                          " s; expected increasing times [s]");
    }
  }
}
}  // namespace

void ReadSolver(const Field& solver, SolverSpec* spec) {
  using Analysis = SolverSpec::Analysis;
  using Integrator = SolverSpec::Integrator;
  CheckKeys(solver, kSolverKeys);
  if (solver.Child("analysis").present()) {
    spec->analysis = ReadEnum<Analysis>(
        solver.Child("analysis"), "analysis",
        {{"dynamic", Analysis::kDynamic}, {"static", Analysis::kStatic}, {"eigen", Analysis::kEigen}});
  }
  if (solver.Child("integrator").present()) {
    spec->integrator = ReadEnum<Integrator>(
        solver.Child("integrator"), "integrator",
        {{"energy_decaying", Integrator::kEnergyDecaying},
         {"energy_preserving", Integrator::kEnergyPreserving},
         {"generalized_alpha", Integrator::kGeneralizedAlpha}});
  }
  OverlayNumber(solver, "rho_inf", Quantity{"a spectral radius rho_inf", Bound::kUnitInterval, ""}, &spec->rho_inf);
  OverlayNumber(solver, "t_end", Quantity{"an end time", Bound::kPositive, "s"}, &spec->t_end);
  OverlayNumber(solver, "dt", Quantity{"a time step", Bound::kPositive, "s"}, &spec->dt);
  OverlayNumber(solver, "dt_min", Quantity{"a minimum time step", Bound::kPositive, "s"}, &spec->dt_min);
  OverlayNumber(solver, "dt_max", Quantity{"a maximum time step", Bound::kPositive, "s"}, &spec->dt_max);
  OverlayBool(solver, "adaptive", &spec->adaptive);
  OverlayNumber(solver, "tol", Quantity{"a relative Newton tolerance", Bound::kPositive, ""}, &spec->tol);
  OverlayNumber(solver, "error_tol", Quantity{"a relative local error tolerance", Bound::kPositive, ""},
                &spec->error_tol);
  if (!solver.Child("dt_min").present()) {
    // A tighter tolerance asks for shorter steps where the motion is fast (a blade released from its held shape
    // needs a first step of 9e-8 s at error_tol 1e-6): the default least step shrinks with it, down to the
    // tolerance 1e-7, below which a run that needs ever shorter steps must still end (a fuzzed error_tol of
    // 4.9e-324, test/data/yaml/error_tol_underflow.yaml).
    const SolverSpec defaults;
    constexpr double kTightestFollowed = 1.0e-3;  // of the default error_tol
    spec->dt_min = defaults.dt_min * std::clamp(spec->error_tol / defaults.error_tol, kTightestFollowed, 1.0);
  }
  if (solver.Child("error_floor").present()) {
    const Field floor = solver.Child("error_floor");
    CheckKeys(floor, kErrorFloorKeys);
    OverlayNumber(floor, "position", Quantity{"a local position error floor", Bound::kPositive, "m"},
                  &spec->error_floor.position);
    OverlayNumber(floor, "rotation", Quantity{"a local rotation error floor", Bound::kPositive, "rad"},
                  &spec->error_floor.rotation);
    OverlayNumber(floor, "joint", Quantity{"a local joint-variable error floor", Bound::kPositive, "rad or m"},
                  &spec->error_floor.joint);
  }
  OverlayCount(solver, "max_iterations", Quantity{"an iteration count", Bound::kAtLeastOne, ""},
               kMaxNewtonIterations, "Newton iterations per step", &spec->max_iterations);
  OverlayCount(solver, "load_steps", Quantity{"a number of load steps", Bound::kAtLeastOne, ""}, kMaxLoadSteps,
               "load steps", &spec->load_steps);
  OverlayCount(solver, "threads", Quantity{"a thread count", Bound::kAtLeastOne, ""}, kMaxThreads, "threads",
               &spec->threads);
  OverlayBool(solver, "static_first", &spec->static_first);
  OverlayVec3(solver, "gravity", Quantity{"a gravity acceleration", Bound::kAny, "m/s^2"}, &spec->gravity);
  if (solver.Child("eigen").present()) ReadEigen(solver.Child("eigen"), &spec->eigen);
  CheckStepBounds(solver, *spec);
  CheckEigenTimes(solver, *spec);
}

// output.csv or output.bag: refused here, where the message can name this file, rather than when the run opens it.
void OverlayOutputPath(const Field& output, const std::string& key, std::string* path) {
  OverlayString(output, key, kOutputPathExpected, path);
  if (path->empty()) return;
  const std::string error = OutputPathError(*path);
  if (!error.empty()) output.Child(key).Fail(error);
}

void ReadOutput(const Field& output, double t_end, OutputSpec* spec) {
  CheckKeys(output, kOutputKeys);
  OverlayNumber(output, "rate_hz", Quantity{"a sample rate (0: every step)", Bound::kNonNegative, "Hz"},
                &spec->rate_hz);
  OverlayOutputPath(output, "csv", &spec->csv);
  OverlayOutputPath(output, "bag", &spec->bag);
  OverlayBool(output, "allow_large_output", &spec->allow_large_output);
  const Field cycle = output.Child("cycle_from");
  if (!cycle.present()) return;
  OverlayNumber(output, "cycle_from", Quantity{"the start of the cycle report", Bound::kNonNegative, "s"},
                &spec->cycle_from);
  if (spec->cycle_from >= t_end) {
    cycle.Fail(cycle.Text() + " s is not before solver.t_end " + FormatNumber(t_end) +
               " s; expected a time in [0, t_end)");
  }
  if (spec->rate_hz == 0) {
    cycle.Fail("needs equally spaced samples, and output.rate_hz is 0 (every step); expected rate_hz > 0");
  }
}

}  // namespace io
}  // namespace flexmbd
