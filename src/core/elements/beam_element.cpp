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
    // Eigen's atan2 of automatic-differentiation scalars returns dynamic-size derivatives: back to T first.
    const T angle = atan2(s, c);
    ratio = angle / s;
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

// Shape-function values and slopes (d/ds) at a set of points of an element.
struct ShapeTable {
  std::vector<std::vector<double>> N, dNds;
};

ShapeTable TableAt(int order, double length, const std::vector<double>& xi) {
  ShapeTable t;
  for (double x : xi) {
    std::vector<double> N, dN;
    Lagrange(order, x, &N, &dN);
    for (double& d : dN) d *= 2.0 / length;
    t.N.push_back(N);
    t.dNds.push_back(dN);
  }
  return t;
}

}  // namespace

// Everything the strain computation needs that does not change: shape-function tables at the Gauss points.
struct BeamElement::Interpolation {
  int order;
  int reference;  // node the rotations are taken relative to
  ShapeTable gauss;
  std::vector<double> weight_ds;  // Gauss weight times ds/dxi
};

namespace {
BeamElement::Interpolation MakeInterpolation(int order, double length) {
  BeamElement::Interpolation b;
  b.order = order;
  b.reference = order / 2;
  const GaussRule rule = ReducedGauss(order);
  b.gauss = TableAt(order, length, rule.points);
  for (double w : rule.weights) b.weight_ds.push_back(w * 0.5 * length);
  return b;
}

// Section strains [eps; kappa] and section frames at the points of a table, for nodes at x_k + dx_k,
// R_k Exp(dtheta_k) (eqs. (B1)-(B2)).
template <class T>
struct PointStrain {
  V6<T> strain;
  M3<T> R;
};

template <class T>
std::vector<PointStrain<T>> Strains(const BeamElement::Interpolation& b, const ShapeTable& table,
                                    const std::vector<Vec3>& x, const std::vector<Mat3>& R,
                                    const std::vector<V3<T>>& dx, const std::vector<V3<T>>& dtheta) {
  const int n = b.order + 1;
  std::vector<M3<T>> rotation(n);
  for (int k = 0; k < n; ++k) rotation[k] = R[k].cast<T>() * ExpOf<T>(dtheta[k]);
  const M3<T>& R_r = rotation[b.reference];
  std::vector<V3<T>> psi(n, V3<T>::Zero());
  for (int k = 0; k < n; ++k) {
    if (k != b.reference) psi[k] = LogOf<T>(R_r.transpose() * rotation[k]);
  }
  std::vector<PointStrain<T>> points;
  for (size_t g = 0; g < table.N.size(); ++g) {
    V3<T> psi_g = V3<T>::Zero(), dpsi = V3<T>::Zero(), dxds = V3<T>::Zero();
    for (int k = 0; k < n; ++k) {
      psi_g += table.N[g][k] * psi[k];
      dpsi += table.dNds[g][k] * psi[k];
      // Positions relative to the reference node (the shape-function slopes sum to zero): the absolute
      // coordinates would add their round-off to the strains.
      dxds += table.dNds[g][k] * ((x[k] - x[b.reference]).cast<T>() + dx[k]);
    }
    PointStrain<T> p;
    p.R = R_r * ExpOf<T>(psi_g);
    p.strain.template head<3>() = p.R.transpose() * dxds - V3<T>::UnitX();
    p.strain.template tail<3>() = RightJacobianOf<T>(psi_g) * dpsi;
    points.push_back(p);
  }
  return points;
}

// Strains at the points of a table for the configuration itself, and their derivatives with respect to the
// node increments (forward-mode automatic differentiation).
struct StrainJacobian {
  std::vector<Vec6> strain;
  std::vector<Eigen::MatrixXd> B;
  std::vector<Mat3> R;
};

StrainJacobian LineariseAt(const BeamElement::Interpolation& b, const ShapeTable& table, const std::vector<Vec3>& x,
                           const std::vector<Mat3>& R) {
  const int n = b.order + 1;
  std::vector<V3<AutoDiff>> dx(n), dtheta(n);
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < 3; ++i) {
      dx[k][i] = AutoDiff(0.0, kMaxIncrements, 6 * k + i);
      dtheta[k][i] = AutoDiff(0.0, kMaxIncrements, 6 * k + 3 + i);
    }
  }
  StrainJacobian out;
  for (const PointStrain<AutoDiff>& p : Strains<AutoDiff>(b, table, x, R, dx, dtheta)) {
    Vec6 e;
    Eigen::MatrixXd B(6, 6 * n);
    for (int i = 0; i < 6; ++i) {
      e[i] = p.strain[i].value();
      B.row(i) = p.strain[i].derivatives().head(6 * n).transpose();
    }
    Mat3 R_p;
    for (int i = 0; i < 9; ++i) R_p(i % 3, i / 3) = p.R(i % 3, i / 3).value();
    out.strain.push_back(e);
    out.B.push_back(B);
    out.R.push_back(R_p);
  }
  return out;
}
}  // namespace

BeamElement::BeamElement(std::string name, std::vector<int> nodes, double length,
                         const Eigen::Matrix<double, 6, 6>& stiffness, double damping)
    : name_(std::move(name)), nodes_(std::move(nodes)), length_(length), stiffness_(stiffness), damping_(damping) {
  order_ = static_cast<int>(nodes_.size()) - 1;
  FLEXMBD_DEMAND(order_ >= 1 && order_ <= 3 && length_ > 0 && damping_ >= 0);
  interpolation_ = std::make_shared<const Interpolation>(MakeInterpolation(order_, length_));
  for (int node : nodes_) {
    for (int k = 0; k < 6; ++k) unknowns_.push_back(6 * node + k);
  }
}

std::vector<Vec6> BeamElement::GaussStrains(const Configuration& c) const {
  const std::vector<V3<double>> zero(order_ + 1, Vec3::Zero());
  std::vector<Vec6> strains;
  for (const PointStrain<double>& p : Strains<double>(*interpolation_, interpolation_->gauss, c.x, c.R, zero, zero)) {
    strains.push_back(p.strain);
  }
  return strains;
}

double BeamElement::Energy(const std::vector<Vec6>& strains) const {
  double energy = 0.0;
  for (size_t g = 0; g < strains.size(); ++g) {
    energy += 0.5 * interpolation_->weight_ds[g] * strains[g].dot(stiffness_ * strains[g]);
  }
  return energy;
}

BeamElement::Linearisation BeamElement::Linearise(const Configuration& c) const {
  StrainJacobian j = LineariseAt(*interpolation_, interpolation_->gauss, c.x, c.R);
  return Linearisation{std::move(j.strain), std::move(j.B)};
}

Eigen::VectorXd BeamElement::NodalForces(const Linearisation& lin, const std::vector<Vec6>& stress) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * (order_ + 1));
  for (size_t g = 0; g < stress.size(); ++g) f += interpolation_->weight_ds[g] * (lin.B[g].transpose() * stress[g]);
  return f;
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
  if (ctx.at_end()) {
    const Linearisation lin = Linearise(end);
    std::vector<Vec6> stress;
    Eigen::VectorXd rates(6 * steps.size());
    for (size_t k = 0; k < steps.size(); ++k) {
      rates.segment<3>(6 * k) = steps[k].v_f;
      rates.segment<3>(6 * k + 3) = steps[k].w_f;
    }
    // Static analysis has no rates; at the end point the strain rate is B (v, w) (B7).
    const bool damped = ctx.mode == AnalysisMode::kEndPoint && damping_ > 0.0;
    for (size_t g = 0; g < lin.strain.size(); ++g) {
      Vec6 e = lin.strain[g];
      if (damped) e += damping_ * (lin.B[g] * rates);
      stress.push_back(stiffness_ * e);
    }
    return NodalForces(lin, stress);
  }
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
  const Linearisation lin = Linearise(mid);
  std::vector<Vec6> stress;
  for (const Vec6& e : lin.strain) stress.push_back(stiffness_ * e);
  Eigen::VectorXd G = NodalForces(lin, stress);
  const std::vector<Vec6> strain_f = GaussStrains(end), strain_i = GaussStrains(start);
  const double V_f = Energy(strain_f), V_i = Energy(strain_i);
  const double mismatch = (V_f - V_i) - G.dot(increments);
  // V_f - V_i carries the round-off of the strains, about eps x / length each, times the stresses: in a stiff
  // section at rest it dwarfs eps V, and the correction (divided by the squared increments) would turn it
  // into forces that Newton cannot remove.
  const double strain_round_off = StrainRoundOff(steps);
  double stress_work = 0;
  for (size_t g = 0; g < stress.size(); ++g) stress_work += interpolation_->weight_ds[g] * stress[g].cwiseAbs().sum();
  const double round_off = 100.0 * std::numeric_limits<double>::epsilon() * (std::abs(V_f) + std::abs(V_i)) +
                           100.0 * strain_round_off * stress_work;
  const double norm = increments.dot(weighted);
  if (std::abs(mismatch) > round_off && norm > 0.0) G += mismatch / norm * weighted;
  if (damping_ > 0.0) G += StepDampingForces(ctx, lin, strain_i, strain_f, increments, weighted, strain_round_off);
  return G;
}

double BeamElement::StrainRoundOff(const std::vector<NodeStep>& steps) const {
  double coordinate = length_;
  for (const NodeStep& s : steps) coordinate = std::max({coordinate, s.x_i.norm(), s.x_f.norm()});
  return std::numeric_limits<double>::epsilon() * coordinate / length_;
}

Eigen::VectorXd BeamElement::StepDampingForces(const StepContext& ctx, const Linearisation& mid,
                                               const std::vector<Vec6>& strain_i, const std::vector<Vec6>& strain_f,
                                               const Eigen::VectorXd& increments, const Eigen::VectorXd& weighted,
                                               double strain_round_off) const {
  // Section forces mu C (e_f - e_i) / h paired with a strain-increment operator B_m = B_mid + (de - B_mid d)
  // (W d)^T / (d^T W d), for which B_m d = de exactly (B7): the forces then do the work
  // -mu sum_g w_g de^T C de / h over the increments d.
  const double norm = increments.dot(weighted);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(increments.size());
  if (!(norm > 0.0)) return f;
  for (size_t g = 0; g < strain_f.size(); ++g) {
    const Vec6 de = strain_f[g] - strain_i[g];
    const Vec6 stress = damping_ * (stiffness_ * de) / ctx.h;
    Vec6 mismatch = de - mid.B[g] * increments;
    if (mismatch.cwiseAbs().maxCoeff() <= 100.0 * strain_round_off) mismatch.setZero();  // round-off, as above
    f += interpolation_->weight_ds[g] * (mid.B[g].transpose() * stress + mismatch.dot(stress) / norm * weighted);
  }
  return f;
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
  // At the end point the velocities move with the configuration by dvf_ddx, dwf_dtheta (damping).
  const double step_x = 1.0e-5 * length_, step_theta = 1.0e-5;
  const std::vector<NodeStep> steps = Gather(ctx, nodes_);
  auto moved = [&](int j, double step) {
    std::vector<NodeStep> moved_steps = steps;
    NodeStep& s = moved_steps[j / 6];
    s = PerturbNodeStep(steps[j / 6], step * Vec6::Unit(j % 6), ctx.mode);
    s.v_f = steps[j / 6].v_f;
    s.w_f = steps[j / 6].w_f;
    if (j % 6 < 3) s.v_f[j % 3] += steps[j / 6].dvf_ddx * step;
    if (j % 6 >= 3) s.w_f[j % 3] += steps[j / 6].dwf_dtheta * step;
    return moved_steps;
  };
  for (int j = 0; j < num_local(); ++j) {
    const double step = j % 6 < 3 ? step_x : step_theta;
    J.col(j) += (Forces(ctx, moved(j, step)) - Forces(ctx, moved(j, -step))) / (2.0 * step);
  }
}

void BeamElement::AddEnergy(const State& state, const Vec3&, EnergyTally* tally) const {
  tally->potential += Energy(GaussStrains(AtState(state)));
}

void BeamElement::AddStepWork(const StepContext& ctx, StepWork* work) const {
  if (ctx.mode != AnalysisMode::kDynamic || damping_ == 0.0) return;
  Configuration start, end;
  for (const NodeStep& s : Gather(ctx, nodes_)) {
    start.x.push_back(s.x_i);
    start.R.push_back(s.R_i);
    end.x.push_back(s.x_f);
    end.R.push_back(s.R_f);
  }
  const std::vector<Vec6> strain_i = GaussStrains(start), strain_f = GaussStrains(end);
  for (size_t g = 0; g < strain_f.size(); ++g) {
    const Vec6 de = strain_f[g] - strain_i[g];
    work->dissipated += interpolation_->weight_ds[g] * damping_ * de.dot(stiffness_ * de) / ctx.h;
  }
}

BeamElement::Section BeamElement::SectionAt(const State& state, double s) const {
  FLEXMBD_DEMAND(s >= -1.0e-12 * length_ && s <= length_ * (1.0 + 1.0e-12));
  const Configuration c = AtState(state);
  const double xi = 2.0 * s / length_ - 1.0;
  const ShapeTable table = TableAt(order_, length_, {xi});
  Section section;
  section.R = LineariseAt(*interpolation_, table, c.x, c.R).R[0];
  for (int k = 0; k <= order_; ++k) section.x += table.N[0][k] * c.x[k];
  // Strains are recovered at the Gauss points, where the reduced rule makes them accurate (the shear strains
  // between them carry the parasitic part that reduced integration removes from the energy), and carried to
  // s by the polynomial through them (docs/theory.md, "Station outputs").
  const StrainJacobian gauss = LineariseAt(*interpolation_, interpolation_->gauss, c.x, c.R);
  Eigen::VectorXd rates(6 * (order_ + 1));
  for (int k = 0; k <= order_; ++k) {
    rates.segment<3>(6 * k) = state.nodes[nodes_[k]].v;
    rates.segment<3>(6 * k + 3) = state.nodes[nodes_[k]].w;
  }
  const std::vector<double>& points = ReducedGauss(order_).points;
  section.strain.setZero();
  Vec6 strain_and_damping = Vec6::Zero();
  for (size_t g = 0; g < points.size(); ++g) {
    double weight = 1.0;
    for (size_t m = 0; m < points.size(); ++m) {
      if (m != g) weight *= (xi - points[m]) / (points[g] - points[m]);
    }
    section.strain += weight * gauss.strain[g];
    strain_and_damping += weight * (gauss.strain[g] + damping_ * (gauss.B[g] * rates));
  }
  section.load = stiffness_ * strain_and_damping;
  return section;
}

}  // namespace flexmbd
