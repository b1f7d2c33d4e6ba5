// Eigen-analysis entry points: choice of method, velocity scaling, parameter sweeps and mode tracking
// (docs/theory.md, "Eigen-analysis").

#include "flexmbd/solver/eigen_analysis.hpp"

#include <algorithm>
#include <utility>

#include "eigen_internal.hpp"
#include "flexmbd/common/error.hpp"

namespace flexmbd {

EigenResult SolveModes(const Model& model, const LinearisedSystem& system, const EigenOptions& options) {
  const int nk = static_cast<int>(system.M.rows());
  if (model.num_element_states() > 0) {
    if (options.method == EigenMethod::kSparse) {
      throw SolverError("eigen-analysis: the sparse method does not take element states (" +
                        model.DescribeUnknown(model.element_state_unknown(0)) + "); expected method dense or auto");
    }
    return eigen_internal::SolveDenseWithStates(model, system, options);
  }
  const bool sparse =
      options.method == EigenMethod::kSparse || (options.method == EigenMethod::kAuto && nk > options.dense_limit);
  return sparse ? eigen_internal::SolveSparse(model, system, options)
                : eigen_internal::SolveDense(model, system, options);
}

EigenResult EigenAnalysis(const Model& model, const State& state, const EigenOptions& options) {
  return SolveModes(model, Linearise(model, state, options.reference), options);
}

State ScaleVelocities(const State& state, double factor) {
  State out = state;
  const double f2 = factor * factor;
  for (NodeState& n : out.nodes) {
    n.v *= factor;
    n.w *= factor;
    n.a_prev *= f2;
    n.alpha_prev *= f2;
    n.a_prev2 *= f2;
    n.alpha_prev2 *= f2;
    n.a_alg *= f2;
    n.alpha_alg *= f2;
  }
  out.qdot *= factor;
  out.qddot_prev *= f2;
  out.qddot_prev2 *= f2;
  out.qacc_alg *= f2;
  out.element_state_rates *= factor;
  out.element_state_rates_alg *= factor;
  out.peak_speed *= std::abs(factor);
  out.peak_spin *= std::abs(factor);
  return out;
}

std::vector<SweepPoint> EigenSweep(const Model& model, const std::vector<double>& parameters,
                                   const std::function<State(double)>& state_at, const EigenOptions& options) {
  std::vector<SweepPoint> points;
  for (double p : parameters) points.push_back({p, EigenAnalysis(model, state_at(p), options)});
  TrackModes(&points);
  return points;
}

std::vector<SweepPoint> EigenSweep(const std::vector<double>& parameters,
                                   const std::function<SweepCase(double)>& case_at, const EigenOptions& options) {
  std::vector<SweepPoint> points;
  for (double p : parameters) {
    const SweepCase c = case_at(p);
    points.push_back({p, EigenAnalysis(c.model, c.state, options)});
  }
  TrackModes(&points);
  return points;
}

namespace {
// Modal assurance criterion of two shapes: 1 for parallel, 0 for orthogonal.
double Mac(const Eigen::Ref<const Eigen::VectorXcd>& a, const Eigen::Ref<const Eigen::VectorXcd>& b) {
  const double denominator = a.squaredNorm() * b.squaredNorm();
  return denominator > 0 ? std::norm(a.dot(b)) / denominator : 0.0;
}
}  // namespace

void TrackModes(std::vector<SweepPoint>* points) {
  for (size_t p = 1; p < points->size(); ++p) {
    const std::vector<Mode>& previous = (*points)[p - 1].result.modes;
    std::vector<Mode>& current = (*points)[p].result.modes;
    if (previous.empty() || current.empty() || previous.front().shape.size() != current.front().shape.size()) continue;
    const int np = static_cast<int>(previous.size()), nc = static_cast<int>(current.size());
    // The inflow states' real roots crowd (Peters' states of every strip), and every oscillating mode drives the
    // states much alike: their entries would make unrelated modes look alike.
    const Eigen::Index motion = previous.front().shape.size() - (*points)[p].result.num_states;
    Eigen::MatrixXd mac(np, nc);
    for (int i = 0; i < np; ++i) {
      for (int j = 0; j < nc; ++j) mac(i, j) = Mac(previous[i].shape.head(motion), current[j].shape.head(motion));
    }
    // Greedy assignment: the best-matching pair first.
    std::vector<int> assigned(np, -1);
    std::vector<bool> taken(nc, false);
    for (int round = 0; round < std::min(np, nc); ++round) {
      Eigen::Index i = 0, j = 0;
      mac.maxCoeff(&i, &j);
      assigned[i] = static_cast<int>(j);
      taken[j] = true;
      mac.row(i).setConstant(-1.0);
      mac.col(j).setConstant(-1.0);
    }
    std::vector<Mode> ordered;
    for (int i = 0; i < np; ++i) {
      if (assigned[i] >= 0) ordered.push_back(current[assigned[i]]);
    }
    for (int j = 0; j < nc; ++j) {
      if (!taken[j]) ordered.push_back(current[j]);
    }
    current = std::move(ordered);
  }
}

}  // namespace flexmbd
