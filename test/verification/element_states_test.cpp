// Element-owned first-order states (docs/theory.md, (S1)-(S4), (E7)): a lag driven by a known input and a
// Maxwell element (spring in series with a dashpot) on a mass-spring, against their closed-form solutions.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <memory>
#include <vector>

#include "case_builders.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "flexmbd/solver/static_solver.hpp"

namespace flexmbd {
namespace element_states_test {

// Lag x' = (u(t) - x) / tau with u = u0 + u1 sin(w t), coupled to nothing. Its equation in the form (S1):
// tau x' + x - u(t) = 0, read at the scheme's time (mid-step, or the end).
constexpr double kTau = 0.2, kU0 = 0.5, kU1 = 1.0, kOmega = 5.0;  // [s], [-], [-], [rad/s]

class Lag : public Element {
 public:
  explicit Lag(int state_unknown) { unknowns_ = {state_unknown}; }
  int num_states() const override { return 1; }
  std::string StateName(int) const override { return "x"; }
  std::string StateOwnerName() const override { return "lag"; }

  static double Input(double t) { return kU0 + kU1 * std::sin(kOmega * t); }

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override {
    const ElementStateStep& x = (*ctx.element_states)[first_state()];
    const double t = ctx.at_end() ? ctx.t_f : 0.5 * (ctx.t_i + ctx.t_f);
    r[0] += kTau * x.rate + x.value - Input(t);
    magnitude[0] += std::abs(kTau * x.rate) + std::abs(x.value) + std::abs(Input(t));
  }
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override { J(0, 0) += ctx.mid_rate(); }
  bool HasRateParts(AnalysisMode) const override { return true; }
  void AddRateParts(const StepContext&, Eigen::Ref<Eigen::MatrixXd> D, Eigen::Ref<Eigen::MatrixXd>) const override {
    D(0, 0) += kTau;
  }
};

// The lag's exact response from x(0) = 0.
double LagExact(double t) {
  const double wt = kOmega * kTau, gain = kU1 / (1.0 + wt * wt);
  const double transient = -kU0 + gain * wt;
  return kU0 + gain * (std::sin(kOmega * t) - wt * std::cos(kOmega * t)) + transient * std::exp(-t / kTau);
}

// Maxwell element on joint variable 0: a spring k2 in series with a dashpot c = k2 tau, the inner point x its
// state. Force on q: -k2 (q - x); state equation tau x' + x - q = 0 (the dashpot carries the spring force).
constexpr double kMass = 2.0, kStiffness = 50.0, kSeriesStiffness = 30.0, kAmplitude = 0.1;

class Maxwell : public Element {
 public:
  Maxwell(int variable, int variable_unknown, int state_unknown) : variable_(variable) {
    unknowns_ = {variable_unknown, state_unknown};
  }
  int num_states() const override { return 1; }
  std::string StateName(int) const override { return "x"; }
  std::string StateOwnerName() const override { return "maxwell"; }

  void AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                   Eigen::Ref<Eigen::VectorXd> magnitude) const override {
    const VariableStep& q = (*ctx.variables)[variable_];
    const ElementStateStep& x = (*ctx.element_states)[first_state()];
    const double q_value = ctx.at_end() ? q.q_f : 0.5 * (q.q_i + q.q_f);
    const double force = kSeriesStiffness * (q_value - x.value);
    r[0] += force;
    magnitude[0] += std::abs(force);
    r[1] += kTau * x.rate + x.value - q_value;
    magnitude[1] += std::abs(kTau * x.rate) + std::abs(x.value) + std::abs(q_value);
  }
  void AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const override {
    const double m = ctx.mid_rate();
    J(0, 0) += kSeriesStiffness * m;
    J(0, 1) -= kSeriesStiffness * m;
    J(1, 0) -= m;
    J(1, 1) += m;
  }
  bool HasRateParts(AnalysisMode) const override { return true; }
  void AddRateParts(const StepContext&, Eigen::Ref<Eigen::MatrixXd> D, Eigen::Ref<Eigen::MatrixXd>) const override {
    D(1, 1) += kTau;
  }
  void AddEnergy(const State& state, const Vec3&, EnergyTally* tally) const override {
    const double stretch = state.q[variable_] - state.element_states[first_state()];
    tally->potential += 0.5 * kSeriesStiffness * stretch * stretch;
  }
  // The dashpot's work over a step: its force k2 (q - x) at the midpoint times the state's travel.
  void AddStepWork(const StepContext& ctx, StepWork* work) const override {
    const VariableStep& q = (*ctx.variables)[variable_];
    const ElementStateStep& x = (*ctx.element_states)[first_state()];
    work->dissipated += kSeriesStiffness * (0.5 * (q.q_i + q.q_f) - x.value) * (x.x_f - x.x_i);
  }

 private:
  int variable_;
};

ModelSpec LagSpec(SolverSpec::Integrator integrator, double dt, double t_end) {
  ModelSpec spec = test::MassSpring(kMass, kStiffness, 0.0, integrator, dt, t_end);
  spec.source = "lag (test)";
  spec.custom_elements.push_back({1, [](const Model& model, int first_state) -> std::unique_ptr<Element> {
                                    return std::make_unique<Lag>(model.element_state_unknown(first_state));
                                  }});
  return spec;
}

ModelSpec MaxwellSpec(SolverSpec::Integrator integrator, double dt, double t_end) {
  ModelSpec spec = test::MassSpring(kMass, kStiffness, kAmplitude, integrator, dt, t_end);
  spec.source = "maxwell (test)";
  spec.custom_elements.push_back({1, [](const Model& model, int first_state) -> std::unique_ptr<Element> {
                                    const int v = model.FindVariable("slider");
                                    return std::make_unique<Maxwell>(v, model.variable_unknown(v),
                                                                     model.element_state_unknown(first_state));
                                  }});
  return spec;
}

// Largest |x - exact| over the accepted steps of a run to t_end (the model samples every step: rate_hz 0), and
// the number of steps.
template <class Exact, class Read>
double RunError(const Model& model, const Exact& exact, const Read& read, long* steps = nullptr) {
  EXPECT_EQ(model.output().rate_hz, 0.0);
  Simulation simulation(model);
  double worst = 0;
  simulation.Run([&](const OutputSample&) {
    worst = std::max(worst, std::abs(read(simulation.state()) - exact(simulation.state().t)));
  });
  if (steps) *steps = simulation.statistics().accepted;
  return worst;
}

double LagState(const State& s) { return s.element_states[0]; }

TEST(ElementStates, UnknownsFollowTheVariablesAndAreNamed) {
  const Model model = BuildModel(LagSpec(SolverSpec::Integrator::kEnergyDecaying, 0.01, 1.0));
  ASSERT_EQ(model.num_element_states(), 1);
  EXPECT_EQ(model.element_state_unknown(0), 6 * model.num_nodes() + model.num_variables());
  EXPECT_EQ(model.multiplier_unknown(0), model.element_state_unknown(0) + 1);
  EXPECT_TRUE(model.is_force_row(model.element_state_unknown(0)));
  EXPECT_TRUE(model.is_state_row(model.element_state_unknown(0)));
  EXPECT_EQ(model.DescribeUnknown(model.element_state_unknown(0)), "lag x");
  EXPECT_EQ(model.initial_state().element_states.size(), 1);
}

TEST(ElementStates, LagFollowsItsInputAtDefaultSettings) {
  // Default solver settings (adaptive energy-decaying steps, error_tol 1e-4) over five time constants and four
  // input periods: the local error test keeps each step's error below 1e-4 of the state's travel, so the
  // accumulated error stays far below 1e-3 of the input amplitude.
  ModelSpec spec = LagSpec(SolverSpec::Integrator::kEnergyDecaying, 0.01, 5.0);
  spec.solver = SolverSpec();
  spec.solver.t_end = 5.0;
  const Model model = BuildModel(spec);
  long steps = 0;
  constexpr double kTolerance = 1.0e-3 * kU1;
  EXPECT_LT(RunError(model, LagExact, LagState, &steps), kTolerance);
  EXPECT_GT(steps, 20);  // the error test, not dt_max, sets the steps
}

// Errors at t = 1 s for dt, dt/2, dt/4 on fixed steps: a second-order scheme divides them by ~4.
void ExpectSecondOrder(SolverSpec::Integrator integrator) {
  std::vector<double> errors;
  for (double dt : {0.02, 0.01, 0.005}) {
    const Model model = BuildModel(LagSpec(integrator, dt, 1.0));
    Simulation simulation(model);
    simulation.Run([](const OutputSample&) {});
    errors.push_back(std::abs(simulation.state().element_states[0] - LagExact(1.0)));
  }
  // Ratios near 4; 3.5 to 4.5 rejects first (2) and third (8) order.
  for (size_t k = 1; k < errors.size(); ++k) {
    EXPECT_GT(errors[k - 1] / errors[k], 3.5) << "dt halving " << k;
    EXPECT_LT(errors[k - 1] / errors[k], 4.5) << "dt halving " << k;
  }
}

TEST(ElementStates, MidpointRuleIsSecondOrder) { ExpectSecondOrder(SolverSpec::Integrator::kEnergyDecaying); }

TEST(ElementStates, GeneralizedAlphaIsSecondOrder) { ExpectSecondOrder(SolverSpec::Integrator::kGeneralizedAlpha); }

TEST(ElementStates, StaticAnalysisSolvesTheStateEquation) {
  // At t = 0 with no rate the lag's equation says x = u(0) = u0.
  const Model model = BuildModel(LagSpec(SolverSpec::Integrator::kEnergyDecaying, 0.01, 1.0));
  State state = model.initial_state();
  SparseSystem system(model);
  ASSERT_TRUE(SolveStatic(model, &system, &state).converged);
  constexpr double kNewtonTolerance = 1.0e-9;
  EXPECT_NEAR(state.element_states[0], kU0, kNewtonTolerance);
  EXPECT_EQ(state.element_state_rates[0], 0.0);
}

// The Maxwell model's characteristic polynomial m tau s^3 + m s^2 + (k + k2) tau s + k = 0, from
// m q'' + k q + k2 (q - x) = 0 and tau x' = q - x; its roots by the companion matrix.
std::vector<std::complex<double>> MaxwellRoots() {
  const double a = kMass * kTau;
  Eigen::Matrix3d companion = Eigen::Matrix3d::Zero();
  companion(0, 2) = -kStiffness / a;
  companion(1, 0) = companion(2, 1) = 1.0;
  companion(1, 2) = -(kStiffness + kSeriesStiffness) * kTau / a;
  companion(2, 2) = -kMass / a;
  const Eigen::EigenSolver<Eigen::Matrix3d> eig(companion, false);
  return {eig.eigenvalues()[0], eig.eigenvalues()[1], eig.eigenvalues()[2]};
}

TEST(ElementStates, EigenAnalysisGivesTheMaxwellRoots) {
  const Model model = BuildModel(MaxwellSpec(SolverSpec::Integrator::kEnergyDecaying, 0.01, 1.0));
  const EigenResult result = EigenAnalysis(model, model.initial_state(), EigenOptions{});
  // One oscillatory pair and one real root: two modes.
  ASSERT_EQ(result.modes.size(), 2u);
  constexpr double kRootTolerance = 1.0e-9;  // relative: dense eigensolver round-off on O(10) entries
  for (const std::complex<double>& root : MaxwellRoots()) {
    if (root.imag() < 0) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (const Mode& mode : result.modes) nearest = std::min(nearest, std::abs(mode.eigenvalue - root));
    EXPECT_LT(nearest, kRootTolerance * std::abs(root)) << root;
  }
}

// The exact free motion from q = A, q' = 0, x = 0: z' = S z with z = (q, q', x).
double MaxwellExact(double t) {
  Eigen::Matrix3d S;
  S << 0, 1, 0, -(kStiffness + kSeriesStiffness) / kMass, 0, kSeriesStiffness / kMass, 1 / kTau, 0, -1 / kTau;
  const Eigen::EigenSolver<Eigen::Matrix3d> eig(S, true);
  const Eigen::Matrix3cd V = eig.eigenvectors();
  const Eigen::Vector3cd c = V.partialPivLu().solve(Eigen::Vector3cd(kAmplitude, 0, 0));
  std::complex<double> q = 0;
  for (int i = 0; i < 3; ++i) q += V(0, i) * c[i] * std::exp(eig.eigenvalues()[i] * t);
  return q.real();
}

TEST(ElementStates, MaxwellFreeDecayMatchesExactAtDefaultSettings) {
  ModelSpec spec = MaxwellSpec(SolverSpec::Integrator::kEnergyDecaying, 0.01, 2.0);
  spec.solver = SolverSpec();
  spec.solver.t_end = 2.0;
  spec.solver.gravity = Vec3(0, 0, -9.81);
  const Model model = BuildModel(spec);
  // Default error_tol 1e-4 per step over ~2.2 periods: 1e-3 of the amplitude bounds the accumulated error.
  constexpr double kTolerance = 1.0e-3 * kAmplitude;
  EXPECT_LT(RunError(model, MaxwellExact, [](const State& s) { return s.q[0]; }), kTolerance);
}

TEST(ElementStates, MaxwellEnergyBooksBalanceWithTheEnergyPreservingScheme) {
  // The midpoint rule on the state and the trapezoidal scheme on the mass make the spring energy change equal
  // the work of its midpoint force exactly, so kinetic + potential + dashpot work stays at its start value up to
  // the Newton tolerance (1e-12 relative).
  const Model model = BuildModel(MaxwellSpec(SolverSpec::Integrator::kEnergyPreserving, 0.005, 2.0));
  Simulation simulation(model);
  std::vector<double> books;
  simulation.Run([&](const OutputSample& s) { books.push_back(s.total() + s.dissipated); });
  ASSERT_GT(books.size(), 100u);
  constexpr double kBooksTolerance = 1.0e-9;  // relative to the energy
  for (double b : books) EXPECT_NEAR(b, books.front(), kBooksTolerance * std::abs(books.front()));
}

}  // namespace element_states_test
}  // namespace flexmbd
