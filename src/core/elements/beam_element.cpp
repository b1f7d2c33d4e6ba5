#include "flexmbd/elements/beam_element.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace {

using Field = BeamStrainField;
static_assert(Field::kMaxDofs <= kMaxRatePartUnknowns, "a beam's rate parts fit AddSchemeRateTerms' blocks");

}  // namespace

// What a dynamic step's forces need: the configurations at the start, middle and end of the step and the
// increments d, with the metric W of the discrete gradient (B5).
struct BeamElement::StepFields {
  Field::PointVectors start_strains, end_strains;
  std::optional<Field> mid, end;  // end: with the tangent only
  Field::Vector d, Wd, W;      // increments, W d, diag(W)
  double norm = 0;             // d^T W d
  double strain_round_off = 0;  // StrainRoundOff of the step
  Field::IncrementMap to_mid, to_end;
};

struct BeamElement::KeptStrains {
  Field::Nodes nodes;
  Field::PointVectors strains;
  int num_nodes = 0;  // 0: none kept yet

  bool Holds(const Field::Nodes& c, int n) const {
    if (n != num_nodes) return false;
    for (int k = 0; k < n; ++k) {
      if (c.x[k] != nodes.x[k] || c.R[k] != nodes.R[k]) return false;
    }
    return true;
  }
};

struct BeamElement::StrainMemo : ElementWorkspace {
  KeptStrains start, end;
};

std::unique_ptr<ElementWorkspace> BeamElement::MakeWorkspace() const { return std::make_unique<StrainMemo>(); }

BeamElement::Field::PointVectors BeamElement::StrainsAt(const Field::Nodes& nodes, KeptStrains* kept) const {
  const int n = shape_.num_nodes();
  if (kept != nullptr && kept->Holds(nodes, n)) return kept->strains;
  const Field field(shape_, nodes, Field::Order::kStrains);
  Field::PointVectors strains;
  for (int g = 0; g < shape_.num_points; ++g) strains[g] = field.strain(g);
  if (kept != nullptr) {
    kept->nodes = nodes;
    kept->strains = strains;
    kept->num_nodes = n;
  }
  return strains;
}

BeamElement::BeamElement(std::string name, std::vector<int> nodes, double length,
                         const Eigen::Matrix<double, 6, 6>& stiffness, double damping)
    : name_(std::move(name)), nodes_(std::move(nodes)), length_(length), stiffness_(stiffness), damping_(damping) {
  const int order = static_cast<int>(nodes_.size()) - 1;
  FLEXMBD_DEMAND(order >= 1 && order <= 3 && length_ > 0 && damping_ >= 0);
  shape_ = GaussShape(order, length_);
  for (int g = 0; g < shape_.num_points; ++g) weighted_stiffness_[g] = shape_.weight_ds[g] * stiffness_;
  for (int node : nodes_) {
    for (int k = 0; k < 6; ++k) unknowns_.push_back(6 * node + k);
  }
}

double BeamElement::Energy(const Field& field) const {
  double energy = 0.0;
  for (int g = 0; g < field.num_points(); ++g) {
    energy += 0.5 * field.strain(g).dot(weighted_stiffness_[g] * field.strain(g));
  }
  return energy;
}

void BeamElement::StepEnds(const StepContext& ctx, Field::Nodes* start, Field::Nodes* end) const {
  for (size_t k = 0; k < nodes_.size(); ++k) {
    const NodeStep& s = (*ctx.nodes)[nodes_[k]];
    start->x[k] = s.x_i;
    start->R[k] = s.R_i;
    end->x[k] = s.x_f;
    end->R[k] = s.R_f;
  }
}

Field::Nodes BeamElement::AtState(const State& state) const {
  Field::Nodes c;
  for (size_t k = 0; k < nodes_.size(); ++k) {
    c.x[k] = state.nodes[nodes_[k]].x;
    c.R[k] = state.nodes[nodes_[k]].R;
  }
  return c;
}

void BeamElement::Evaluate(const StepContext& ctx, Field::Vector* forces, Field::Matrix* K) const {
  if (ctx.at_end()) {
    EvaluateAtEnd(ctx, forces, K);
  } else {
    EvaluateStep(ctx, forces, K);
  }
}

void BeamElement::EndNodesAndRates(const StepContext& ctx, Field::Nodes* end, Field::Vector* rates) const {
  const int n = shape_.num_nodes();
  rates->resize(6 * n);
  for (int k = 0; k < n; ++k) {
    const NodeStep& s = (*ctx.nodes)[nodes_[k]];
    end->x[k] = s.x_f;
    end->R[k] = s.R_f;
    rates->segment<3>(6 * k) = s.v_f;
    rates->segment<3>(6 * k + 3) = s.w_f;
  }
}

void BeamElement::EvaluateAtEnd(const StepContext& ctx, Field::Vector* forces, Field::Matrix* K) const {
  Field::Nodes end;
  Field::Vector rates;
  EndNodesAndRates(ctx, &end, &rates);
  const Field field(shape_, end, K != nullptr ? Field::Order::kSecond : Field::Order::kFirst);
  // Static analysis has no rates; at the end point the strain rate is B (v, w) (B7).
  const bool damped = HasRateParts(ctx.mode);
  Field::PointVectors stress;
  std::array<Field::Jacobian, BeamShape::kMaxPoints> B;
  for (int g = 0; g < field.num_points(); ++g) {
    Vec6 e = field.strain(g);
    if (damped) {
      B[g] = field.StrainJacobian(g);
      e += damping_ * (B[g] * rates);
    }
    stress[g] = weighted_stiffness_[g] * e;
  }
  *forces += field.Gradient(stress);
  if (K == nullptr) return;
  field.AddTangent(stress, &weighted_stiffness_, K);
  if (!damped) return;
  // d/dp [B (v, w)] at held rates: B moves with the configuration; the part through the rates is AddRateParts'.
  const std::array<Field::Jacobian, BeamShape::kMaxPoints> rate_derivatives = field.StrainJacobianDerivatives(rates);
  for (int g = 0; g < field.num_points(); ++g) {
    K->noalias() += B[g].transpose() * (damping_ * weighted_stiffness_[g]) * rate_derivatives[g];
  }
}

bool BeamElement::HasRateParts(AnalysisMode mode) const {
  return mode == AnalysisMode::kEndPoint && damping_ > 0.0;
}

void BeamElement::AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                               Eigen::Ref<Eigen::MatrixXd>) const {
  // The damping forces B^T mu C B (v, w) of (B7), differentiated with respect to the end rates.
  Field::Nodes end;
  Field::Vector rates;
  EndNodesAndRates(ctx, &end, &rates);
  const Field field(shape_, end, Field::Order::kFirst);
  std::array<Mat6, BeamShape::kMaxPoints> viscous;
  for (int g = 0; g < field.num_points(); ++g) viscous[g] = damping_ * weighted_stiffness_[g];
  D += field.MaterialTangent(field, viscous);
}

double BeamElement::StrainRoundOff(const StepContext& ctx) const {
  double coordinate = length_;
  for (int node : nodes_) {
    const NodeStep& s = (*ctx.nodes)[node];
    coordinate = std::max({coordinate, s.x_i.norm(), s.x_f.norm()});
  }
  return std::numeric_limits<double>::epsilon() * coordinate / length_;
}

void BeamElement::EvaluateStep(const StepContext& ctx, Field::Vector* forces, Field::Matrix* K) const {
  const int n = shape_.num_nodes(), dofs = 6 * n;
  const bool tangent = K != nullptr;
  StepFields step;
  Field::Nodes start, mid, end;
  StepEnds(ctx, &start, &end);
  step.d.resize(dofs);
  step.W.resize(dofs);
  step.to_mid.translation_rate = 0.5;
  for (int k = 0; k < n; ++k) {
    const NodeStep& s = (*ctx.nodes)[nodes_[k]];
    // Along R_i Exp(tau theta) the body-frame rate is theta itself, so the mid-step gradient pairs with the
    // increments directly; theta moving by t moves the middle by T(theta/2) t / 2 and the end by T(theta) t.
    const RotationVectorCalculus half(0.5 * s.theta, RotationVectorCalculus::Level::kMaps);
    mid.x[k] = 0.5 * (s.x_i + s.x_f);
    mid.R[k] = s.R_i * half.exp();
    step.to_mid.rotation[k] = 0.5 * half.tangent();
    step.to_end.rotation[k] = s.T;
    step.d.segment<3>(6 * k) = s.dx;
    step.d.segment<3>(6 * k + 3) = s.theta;
    // Rotations weighted by length^2 so the metric is in consistent units (Gonzalez 1996).
    step.W.segment<3>(6 * k).setConstant(1.0);
    step.W.segment<3>(6 * k + 3).setConstant(length_ * length_);
  }
  step.Wd = step.W.cwiseProduct(step.d);
  step.norm = step.d.dot(step.Wd);
  step.strain_round_off = StrainRoundOff(ctx);
  StrainMemo* memo = WorkspaceIn<StrainMemo>(ctx);
  step.start_strains = StrainsAt(start, memo != nullptr ? &memo->start : nullptr);
  step.mid.emplace(shape_, mid, tangent ? Field::Order::kSecond : Field::Order::kFirst);
  // The end strains of a first-order field are not kept: its rotation ratios are summed from a higher term and
  // may differ in the last bits from the kStrains ones that the step's work and history read.
  if (tangent) {
    step.end.emplace(shape_, end, Field::Order::kFirst);
    for (int g = 0; g < shape_.num_points; ++g) step.end_strains[g] = step.end->strain(g);
  } else {
    step.end_strains = StrainsAt(end, memo != nullptr ? &memo->end : nullptr);
  }
  const StepStress stress = StepStresses(ctx, step);
  *forces += stress.forces;
  if (!tangent) return;
  // The stresses' geometric part at the middle configuration (B12), then their material part and the gap's.
  // The first tangent of a step (without ctx.geometric_stiffness) is assembled at the predictor, whose stresses
  // are spurious: coasting along the tangents of a turning beam stretches it by O(theta^2), and the geometric
  // stiffness of EA times that stretch can outweigh the inertia and make the first Newton increments grow. It
  // leaves the geometric part out, as it does for constraint forces and loads (docs/theory.md, "Newton
  // iteration"); the correction term of (B5) keeps its whole derivative, which takes fewer tangents than
  // leaving K_mid out of it too. The tangent refreshed when that one converges slowly is exact.
  const Field::Vector K_mid_transposed_d = step.mid->AddStepTangent(
      stress.stress, *step.end, stress.rate, step.to_mid, step.to_end, ctx.geometric_stiffness, step.d, K);
  AddGapTangent(step, stress, K_mid_transposed_d, K);
}

void BeamElement::AddCorrectionDerivative(const StepFields& step, double value, const Field::Vector& derivative,
                                          Field::Matrix* K) const {
  // d/dd [value W d / (d^T W d)] = W d [derivative / n - 2 value W d / n^2]^T + (value / n) W, n = d^T W d.
  const Field::Vector row = derivative / step.norm - (2.0 * value / (step.norm * step.norm)) * step.Wd;
  K->noalias() += step.Wd * row.transpose();
  K->diagonal() += (value / step.norm) * step.W;
}

BeamElement::StepStress BeamElement::StepStresses(const StepContext& ctx, const StepFields& step) const {
  // Section forces C (e_i + e_f) / 2, plus mu C (e_f - e_i) / h and the scheme's alpha C (de - de_lagged)
  // (B13), paired with a strain-increment operator B_m = B_mid + (de - B_mid d) (W d)^T / (d^T W d), for which
  // B_m d = de exactly (B5): the forces then do the work V_f - V_i - sum_g w_g [mu de^T C de / h +
  // alpha (de - de_lagged)^T C de]. The mean of the end strains, not the strains of the middle configuration,
  // carries the stress: the chord between two rotated positions is shorter than either, so a beam turning by
  // theta in a step would be compressed by theta^2 / 8 in the middle (B5).
  const Field& mid = *step.mid;
  const double alpha = Alpha(ctx);
  const double viscosity = damping_ / ctx.h + alpha;
  StepStress stress;
  const Field::PointVectors mid_rates = mid.StrainDirectionalDerivatives(step.d);  // B_mid d
  for (int g = 0; g < mid.num_points(); ++g) {
    const Vec6 de = step.end_strains[g] - step.start_strains[g];
    stress.rate[g] = (0.5 + viscosity) * weighted_stiffness_[g];
    stress.stress[g] = weighted_stiffness_[g] * (0.5 * (step.start_strains[g] + step.end_strains[g]) + viscosity * de);
    if (alpha > 0) stress.stress[g] -= alpha * (weighted_stiffness_[g] * LaggedStrainChange(ctx, g));
    stress.gap[g] = de - mid_rates[g];
    // A gap at the round-off of the strains would be divided by the squared increments into forces that
    // Newton cannot remove (a stiff section at rest).
    if (stress.gap[g].cwiseAbs().maxCoeff() <= 100.0 * step.strain_round_off) stress.gap[g].setZero();
    stress.gap_work += stress.gap[g].dot(stress.stress[g]);
  }
  stress.forces = mid.Gradient(stress.stress);
  if (step.norm > 0.0) stress.forces += stress.gap_work / step.norm * step.Wd;
  return stress;
}

void BeamElement::AddGapTangent(const StepFields& step, const StepStress& stress,
                                const Field::Vector& K_mid_transposed_d, Field::Matrix* K) const {
  const int n = shape_.num_nodes();
  if (step.norm == 0.0) return;
  // d gap_work = sum_g [B_end^T rate^T gap + (B_end - B_mid)^T stress], the second term where a gap is left.
  Field::PointVectors on_end, on_mid;
  on_end.fill(Vec6::Zero());  // Gradient reads only num_points entries; set all so that no compiler doubts it
  bool any_gap = false;
  for (int g = 0; g < step.mid->num_points(); ++g) {
    const bool gap = !stress.gap[g].isZero(0.0);
    any_gap = any_gap || gap;
    on_mid[g] = gap ? stress.stress[g] : Vec6::Zero();
    on_end[g] = stress.rate[g].transpose() * stress.gap[g] + on_mid[g];
  }
  Field::Vector dgap_work = step.to_end.ApplyTransposed(n, step.end->Gradient(on_end));
  if (any_gap) dgap_work -= step.mid->Gradient(on_mid);
  // The gap's derivative through B_mid at fixed d, summed against the stresses, is K_mid^T d: both are the
  // second derivative of stress . strain at the middle configuration (BeamStrainField::AddTangent). It is
  // taken over every point once any gap is above round-off (a point whose gap was cut to zero at round-off
  // then contributes the derivative of its uncut gap, which only the convergence rate sees).
  if (any_gap) dgap_work -= K_mid_transposed_d;
  AddCorrectionDerivative(step, stress.gap_work, dgap_work, K);
}

void BeamElement::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                              Eigen::Ref<Eigen::VectorXd> magnitude) const {
  AddResidualAndTangent(ctx, r, magnitude, nullptr);
}

void BeamElement::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  Field::Vector forces = Field::Vector::Zero(num_local());
  Field::Matrix K = Field::Matrix::Zero(num_local(), num_local());
  Evaluate(ctx, &forces, &K);
  J += K;
}

void BeamElement::AddResidualAndTangent(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                                        Eigen::Ref<Eigen::VectorXd> magnitude, Eigen::Ref<Eigen::MatrixXd>* J) const {
  Field::Vector forces = Field::Vector::Zero(num_local());
  Field::Matrix K;
  if (J != nullptr) K.setZero(num_local(), num_local());
  Evaluate(ctx, &forces, J != nullptr ? &K : nullptr);
  r += forces;
  magnitude += forces.cwiseAbs();
  if (J != nullptr) *J += K;
}

void BeamElement::AddEnergy(const State& state, const Vec3&, EnergyTally* tally) const {
  tally->potential += Energy(Field(shape_, AtState(state), Field::Order::kStrains));
}

void BeamElement::AddStepWork(const StepContext& ctx, StepWork* work) const {
  const double alpha = Alpha(ctx);
  if (ctx.mode != AnalysisMode::kDynamic || (damping_ == 0.0 && alpha == 0.0)) return;
  const Field::PointVectors de = StrainChanges(ctx);
  for (int g = 0; g < shape_.num_points; ++g) {
    const Vec6 stress_change = weighted_stiffness_[g] * de[g];
    work->dissipated += damping_ * de[g].dot(stress_change) / ctx.h;
    if (alpha > 0) work->numerical += alpha * (de[g] - LaggedStrainChange(ctx, g)).dot(stress_change);
  }
}

void BeamElement::RecordHistory(const StepContext& ctx, Eigen::VectorXd* history) const {
  const Field::PointVectors de = StrainChanges(ctx);
  for (int g = 0; g < shape_.num_points; ++g) history->segment<6>(6 * g) = de[g];
}

BeamElement::Field::PointVectors BeamElement::StrainChanges(const StepContext& ctx) const {
  Field::Nodes start, end;
  StepEnds(ctx, &start, &end);
  StrainMemo* memo = WorkspaceIn<StrainMemo>(ctx);
  const Field::PointVectors at_start = StrainsAt(start, memo != nullptr ? &memo->start : nullptr);
  const Field::PointVectors at_end = StrainsAt(end, memo != nullptr ? &memo->end : nullptr);
  Field::PointVectors de;
  for (int g = 0; g < shape_.num_points; ++g) de[g] = at_end[g] - at_start[g];
  return de;
}

Vec6 BeamElement::LaggedStrainChange(const StepContext& ctx, int point) const {
  // (h / h_prev) de_prev, as dq_lagged for springs; Alpha() is nonzero only once a step has been taken.
  return ctx.h / ctx.start->h_prev * ctx.start->element_history[index()].segment<6>(6 * point);
}

std::array<double, BeamShape::kMaxPoints> BeamElement::StationWeights(double s) const {
  FLEXMBD_DEMAND(s >= -1.0e-12 * length_ && s <= length_ * (1.0 + 1.0e-12));
  const double xi = 2.0 * s / length_ - 1.0;
  std::array<double, BeamShape::kMaxPoints> weights{};
  for (int g = 0; g < shape_.num_points; ++g) {
    weights[g] = 1.0;
    for (int m = 0; m < shape_.num_points; ++m) {
      if (m != g) weights[g] *= (xi - shape_.xi[m]) / (shape_.xi[g] - shape_.xi[m]);
    }
  }
  return weights;
}

BeamElement::Section BeamElement::SectionAt(const State& state, double s) const {
  const Field::Nodes c = AtState(state);
  const BeamShape point = PointShape(shape_.order, length_, 2.0 * s / length_ - 1.0);
  Section section;
  section.R = Field(point, c, Field::Order::kStrains).SectionRotation(0);
  for (int k = 0; k < shape_.num_nodes(); ++k) {
    section.x += point.N[0][k] * c.x[k];
    section.v += point.N[0][k] * state.nodes[nodes_[k]].v;
  }
  // Strains are recovered at the Gauss points, where the reduced rule makes them accurate (the shear strains
  // between them carry the parasitic part that reduced integration removes from the energy), and carried to
  // s by the polynomial through them (docs/theory.md, "Station outputs").
  const Field::PointVectors strains = StrainsAt(c, nullptr);
  const std::array<double, BeamShape::kMaxPoints> weights = StationWeights(s);
  section.strain.setZero();
  for (int g = 0; g < shape_.num_points; ++g) section.strain += weights[g] * strains[g];
  section.load = stiffness_ * section.strain;
  return section;
}

Vec6 BeamElement::DampingLoadAt(const StepContext& step, double s) const {
  if (damping_ == 0.0 || step.mode == AnalysisMode::kStatic) return Vec6::Zero();
  const std::array<double, BeamShape::kMaxPoints> weights = StationWeights(s);
  Vec6 rate = Vec6::Zero();
  if (step.mode == AnalysisMode::kDynamic) {
    // The scheme's end velocities are no rigid field in a rigid rotation (the trapezoidal relation (T3) makes a
    // node on a circle faster than its turn), so B (v_f, w_f) would strain a spinning beam. The strains are
    // objective: their change over the step gives the rate the step's damping applied.
    const Field::PointVectors de = StrainChanges(step);
    for (int g = 0; g < shape_.num_points; ++g) rate += weights[g] * de[g];
    rate /= step.h;
  } else {
    Field::Nodes end;
    Field::Vector rates;
    EndNodesAndRates(step, &end, &rates);
    const Field field(shape_, end, Field::Order::kFirst);
    for (int g = 0; g < shape_.num_points; ++g) rate += weights[g] * (field.StrainJacobian(g) * rates);
  }
  return damping_ * (stiffness_ * rate);
}

}  // namespace flexmbd
