#include "flexmbd/elements/beam_element.hpp"

#include <cmath>
#include <limits>

#include <unsupported/Eigen/AutoDiff>

#include "flexmbd/common/error.hpp"
#include "flexmbd/math/so3_generic.hpp"

namespace flexmbd {
namespace {

constexpr int kMaxIncrements = 6 * BeamElement::kMaxNodes;
using Derivatives = Eigen::Matrix<double, kMaxIncrements, 1>;
using AutoDiff = Eigen::AutoDiffScalar<Derivatives>;
template <class T>
using V3 = Eigen::Matrix<T, 3, 1>;
template <class T>
using M3 = Eigen::Matrix<T, 3, 3>;
template <class T>
using V6 = Eigen::Matrix<T, 6, 1>;

using so3::ExpOf;
using so3::RightJacobianOf;
using so3::ValueOf;

// Rotation vector of R (angle below pi/2 in a beam element): a = axial(R) = sin(angle) n, psi = angle/sin * a.
template <class T>
V3<T> LogOf(const M3<T>& R) {
  using std::atan2;
  using std::sqrt;
  const V3<T> a(0.5 * (R(2, 1) - R(1, 2)), 0.5 * (R(0, 2) - R(2, 0)), 0.5 * (R(1, 0) - R(0, 1)));
  const T c = 0.5 * (R.trace() - 1.0);
  const T s2 = a.squaredNorm();
  T ratio;
  if (ValueOf(s2) < 1.0e-6 && ValueOf(c) > 0.0) {
    // asin(s)/s = 1 + s^2/6 + 3 s^4/40 + 5 s^6/112 + ...; the next term is < 1e-20 here.
    ratio = 1.0 + s2 / 6.0 + 3.0 * s2 * s2 / 40.0 + 5.0 * s2 * s2 * s2 / 112.0;
  } else {
    const T s = sqrt(s2);
    ratio = atan2(s, c) / s;
  }
  return ratio * a;
}

// Gauss points and weights on [-1, 1].
struct GaussRule {
  std::vector<double> points, weights;
};
GaussRule ReducedGauss(int order) {
  switch (order) {
    case 1: return {{0.0}, {2.0}};
    case 2: return {{-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)}, {1.0, 1.0}};
    default: return {{-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
  }
}

// Lagrange shape functions on equally spaced nodes and their derivatives with respect to xi.
void Lagrange(int order, double xi, std::vector<double>* N, std::vector<double>* dN) {
  const int n = order + 1;
  std::vector<double> nodes(n);
  for (int k = 0; k < n; ++k) nodes[k] = -1.0 + 2.0 * k / order;
  N->assign(n, 1.0);
  dN->assign(n, 0.0);
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      if (j == k) continue;
      (*N)[k] *= (xi - nodes[j]) / (nodes[k] - nodes[j]);
      double term = 1.0 / (nodes[k] - nodes[j]);
      for (int m = 0; m < n; ++m) {
        if (m != k && m != j) term *= (xi - nodes[m]) / (nodes[k] - nodes[m]);
      }
      (*dN)[k] += term;
    }
  }
}

}  // namespace

// Everything the strain computation needs that does not change: shape-function tables at the Gauss points.
struct BeamElement::Interpolation {
  int order;
  int reference;  // node the rotations are taken relative to
  std::vector<std::vector<double>> N, dNds;
  std::vector<double> weight_ds;  // Gauss weight times ds/dxi
  std::vector<double> s;          // Gauss point positions from the first node
};

namespace {
BeamElement::Interpolation MakeInterpolation(int order, double length) {
  BeamElement::Interpolation b;
  b.order = order;
  b.reference = order / 2;
  const GaussRule rule = ReducedGauss(order);
  for (size_t g = 0; g < rule.points.size(); ++g) {
    std::vector<double> N, dN;
    Lagrange(order, rule.points[g], &N, &dN);
    for (double& d : dN) d *= 2.0 / length;
    b.N.push_back(N);
    b.dNds.push_back(dN);
    b.weight_ds.push_back(rule.weights[g] * 0.5 * length);
    b.s.push_back(0.5 * length * (rule.points[g] + 1.0));
  }
  return b;
}

// Section strains [eps; kappa] at each Gauss point for nodes at x_k + dx_k, R_k Exp(dtheta_k) (eqs. (B2)).
template <class T>
std::vector<V6<T>> Strains(const BeamElement::Interpolation& b, const std::vector<Vec3>& x, const std::vector<Mat3>& R,
                           const std::vector<V3<T>>& dx, const std::vector<V3<T>>& dtheta) {
  const int n = b.order + 1;
  std::vector<M3<T>> rotation(n);
  for (int k = 0; k < n; ++k) rotation[k] = R[k].cast<T>() * ExpOf<T>(dtheta[k]);
  const M3<T>& R_r = rotation[b.reference];
  std::vector<V3<T>> psi(n, V3<T>::Zero());
  for (int k = 0; k < n; ++k) {
    if (k != b.reference) psi[k] = LogOf<T>(R_r.transpose() * rotation[k]);
  }
  std::vector<V6<T>> strains;
  for (size_t g = 0; g < b.N.size(); ++g) {
    V3<T> psi_g = V3<T>::Zero(), dpsi = V3<T>::Zero(), dxds = V3<T>::Zero();
    for (int k = 0; k < n; ++k) {
      psi_g += b.N[g][k] * psi[k];
      dpsi += b.dNds[g][k] * psi[k];
      // Positions relative to the reference node (the shape-function slopes sum to zero): the absolute
      // coordinates would add their round-off to the strains.
      dxds += b.dNds[g][k] * ((x[k] - x[b.reference]).cast<T>() + dx[k]);
    }
    const M3<T> R_g = R_r * ExpOf<T>(psi_g);
    V6<T> e;
    e.template head<3>() = R_g.transpose() * dxds - V3<T>::UnitX();
    e.template tail<3>() = RightJacobianOf<T>(psi_g) * dpsi;
    strains.push_back(e);
  }
  return strains;
}

template <class T>
T EnergyOf(const BeamElement::Interpolation& b, const Eigen::Matrix<double, 6, 6>& C, const std::vector<Vec3>& x,
           const std::vector<Mat3>& R, const std::vector<V3<T>>& dx, const std::vector<V3<T>>& dtheta) {
  const std::vector<V6<T>> strains = Strains<T>(b, x, R, dx, dtheta);
  T energy = T(0.0);
  for (size_t g = 0; g < strains.size(); ++g) {
    energy += 0.5 * b.weight_ds[g] * strains[g].dot(C.cast<T>() * strains[g]);
  }
  return energy;
}
}  // namespace

BeamElement::BeamElement(std::string name, std::vector<int> nodes, double length, const BeamSectionSpec& section)
    : name_(std::move(name)), nodes_(std::move(nodes)), length_(length), stiffness_(section.stiffness) {
  order_ = static_cast<int>(nodes_.size()) - 1;
  FLEXMBD_DEMAND(order_ >= 1 && order_ <= 3 && length_ > 0);
  interpolation_ = std::make_shared<const Interpolation>(MakeInterpolation(order_, length_));
  for (int node : nodes_) {
    for (int k = 0; k < 6; ++k) unknowns_.push_back(6 * node + k);
  }
}

double BeamElement::Energy(const Configuration& c) const {
  const int n = order_ + 1;
  const std::vector<V3<double>> zero(n, Vec3::Zero());
  return EnergyOf<double>(*interpolation_, stiffness_, c.x, c.R, zero, zero);
}

Eigen::VectorXd BeamElement::Gradient(const Configuration& c) const {
  const int n = order_ + 1;
  std::vector<V3<AutoDiff>> dx(n), dtheta(n);
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < 3; ++i) {
      dx[k][i] = AutoDiff(0.0, kMaxIncrements, 6 * k + i);
      dtheta[k][i] = AutoDiff(0.0, kMaxIncrements, 6 * k + 3 + i);
    }
  }
  const AutoDiff energy = EnergyOf<AutoDiff>(*interpolation_, stiffness_, c.x, c.R, dx, dtheta);
  return energy.derivatives().head(6 * n);
}

BeamElement::Configuration BeamElement::AtState(const State& state) const {
  Configuration c;
  for (int node : nodes_) {
    c.x.push_back(state.nodes[node].x);
    c.R.push_back(state.nodes[node].R);
  }
  return c;
}

Eigen::VectorXd BeamElement::Forces(const StepContext& ctx, const std::vector<NodeStep>& steps) const {
  Configuration end, mid, start;
  for (const NodeStep& s : steps) {
    end.x.push_back(s.x_f);
    end.R.push_back(s.R_f);
  }
  if (ctx.at_end()) return Gradient(end);
  Eigen::VectorXd increments(6 * steps.size()), weighted(6 * steps.size());
  for (size_t k = 0; k < steps.size(); ++k) {
    const NodeStep& s = steps[k];
    start.x.push_back(s.x_i);
    start.R.push_back(s.R_i);
    mid.x.push_back(0.5 * (s.x_i + s.x_f));
    mid.R.push_back(s.R_i * Exp(0.5 * s.theta));
    increments.segment<3>(6 * k) = s.dx;
    increments.segment<3>(6 * k + 3) = s.theta;
    // Rotations weighted by length^2 so the metric is in consistent units (Gonzalez 1996).
    weighted.segment<3>(6 * k) = s.dx;
    weighted.segment<3>(6 * k + 3) = length_ * length_ * s.theta;
  }
  // Along R_i Exp(tau theta) the body-frame rate is theta itself, so the mid-step gradient pairs with the
  // increments directly; the correction makes G . increments = V_f - V_i exactly.
  Eigen::VectorXd G = Gradient(mid);
  const double V_f = Energy(end), V_i = Energy(start);
  const double mismatch = (V_f - V_i) - G.dot(increments);
  const double round_off = 100.0 * std::numeric_limits<double>::epsilon() * (std::abs(V_f) + std::abs(V_i));
  const double norm = increments.dot(weighted);
  if (std::abs(mismatch) > round_off && norm > 0.0) G += mismatch / norm * weighted;
  return G;
}

namespace {
std::vector<NodeStep> Gather(const StepContext& ctx, const std::vector<int>& nodes) {
  std::vector<NodeStep> steps;
  for (int node : nodes) steps.push_back((*ctx.nodes)[node]);
  return steps;
}
}  // namespace

void BeamElement::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                              Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const Eigen::VectorXd forces = Forces(ctx, Gather(ctx, nodes_));
  r += forces;
  magnitude += forces.cwiseAbs();
}

void BeamElement::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  // Central differences of the exact forces: truncation O(step^2) ~ 1e-10 relative and round-off
  // eps |forces| / step stay small enough for the condition numbers of slender beams (EA L^2 / EI ~ 1e6).
  const double step_x = 1.0e-5 * length_, step_theta = 1.0e-5;
  const std::vector<NodeStep> steps = Gather(ctx, nodes_);
  for (int j = 0; j < num_local(); ++j) {
    std::vector<NodeStep> plus = steps, minus = steps;
    const double step = j % 6 < 3 ? step_x : step_theta;
    plus[j / 6] = PerturbNodeStep(steps[j / 6], step * Vec6::Unit(j % 6), ctx.mode);
    minus[j / 6] = PerturbNodeStep(steps[j / 6], -step * Vec6::Unit(j % 6), ctx.mode);
    J.col(j) += (Forces(ctx, plus) - Forces(ctx, minus)) / (2.0 * step);
  }
}

void BeamElement::AddEnergy(const State& state, const Vec3&, EnergyTally* tally) const {
  tally->potential += Energy(AtState(state));
}

std::vector<BeamElement::SectionSample> BeamElement::SectionSamples(const State& state) const {
  const Configuration c = AtState(state);
  const Interpolation& b = *interpolation_;
  const std::vector<V3<double>> zero(order_ + 1, Vec3::Zero());
  const std::vector<V6<double>> strains = Strains<double>(b, c.x, c.R, zero, zero);
  std::vector<SectionSample> samples;
  for (size_t g = 0; g < strains.size(); ++g) samples.push_back({b.s[g], strains[g], stiffness_ * strains[g]});
  return samples;
}

}  // namespace flexmbd
