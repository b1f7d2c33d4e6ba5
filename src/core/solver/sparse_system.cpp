#include "flexmbd/solver/sparse_system.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <utility>

#include <klu.h>

#include "flexmbd/common/error.hpp"
#include "flexmbd/model/model.hpp"
#include "parallel_assembly.hpp"

namespace flexmbd {

struct SparseSystem::KluFactorisation {
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  klu_common common;
  double pivoted_growth = 0;  ///< reciprocal pivot growth of the last factorisation with fresh pivoting
};

namespace {
// A refactorisation keeps the pivot order of the last fresh factorisation; it is redone with fresh pivoting when
// its reciprocal pivot growth (KLU's rgrowth, min over columns of max|A| / max|U|) falls below this fraction of
// the fresh one, i.e. when the old order lets entries grow 100x more than pivoting would, costing about two
// digits of the solve. (The diagonal ratio klu_rcond is no test here: the zero-diagonal constraint blocks give
// pivots near 1/stiffness, so even freshly pivoted factors of well-posed models show 1e-10 to 1e-23.)
constexpr double kRefactorGrowthRatio = 1.0e-2;


double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

SparseSystem::SparseSystem(const Model& model)
    : model_(model), n_(model.num_unknowns()), threads_(model.solver().threads) {
  std::vector<std::set<int>> rows_of_column(n_);
  int max_local = 0;
  for (const auto& element : model.elements()) {
    const std::vector<int>& u = element->unknowns();
    max_local = std::max(max_local, element->num_local());
    for (int col : u) rows_of_column[col].insert(u.begin(), u.end());
  }
  column_start_.assign(n_ + 1, 0);
  for (int c = 0; c < n_; ++c) {
    column_start_[c + 1] = column_start_[c] + static_cast<int>(rows_of_column[c].size());
    row_index_.insert(row_index_.end(), rows_of_column[c].begin(), rows_of_column[c].end());
  }
  values_.assign(row_index_.size(), 0.0);
  scaled_values_.assign(row_index_.size(), 0.0);
  for (const auto& element : model.elements()) {
    const std::vector<int>& u = element->unknowns();
    const int m = element->num_local();
    std::vector<int> positions(static_cast<size_t>(m) * m);
    for (int j = 0; j < m; ++j) {
      const auto first = row_index_.begin() + column_start_[u[j]];
      const auto last = row_index_.begin() + column_start_[u[j] + 1];
      for (int i = 0; i < m; ++i) {
        positions[j * m + i] = static_cast<int>(std::lower_bound(first, last, u[i]) - row_index_.begin());
      }
    }
    scatter_.push_back(std::move(positions));
  }
  residual_.resize(n_);
  magnitude_.resize(n_);
  row_abs_sum_ = Eigen::VectorXd::Zero(n_);
  row_scale_ = Eigen::VectorXd::Ones(n_);
  factor_scale_ = Eigen::VectorXd::Ones(n_);
  local_r_.resize(max_local);
  local_m_.resize(max_local);
  local_J_.resize(max_local, max_local);
  klu_ = std::make_unique<KluFactorisation>();
  klu_defaults(&klu_->common);
  klu_->common.scale = -1;  // the values come scaled (scaled_values_): no scaling, no checks of the pattern
  if (threads_ > 1 && model.elements().size() > 1) {
    parallel_ = std::make_unique<ParallelAssembly>(model.elements(), threads_);
  }
}

SparseSystem::~SparseSystem() {
  if (klu_->numeric) klu_free_numeric(&klu_->numeric, &klu_->common);
  if (klu_->symbolic) klu_free_symbolic(&klu_->symbolic, &klu_->common);
}

void SparseSystem::Assemble(const StepContext& ctx, bool with_tangent) {
  const auto start = std::chrono::steady_clock::now();
  residual_.setZero();
  magnitude_.setZero();
  if (with_tangent) std::fill(values_.begin(), values_.end(), 0.0);
  const ElementBlocks scratch{local_r_.data(), local_m_.data(), local_J_.data(), static_cast<int>(local_J_.rows())};
  const auto add = [&](int e, const ElementBlocks& blocks) { AddElement(e, blocks, with_tangent); };
  const bool parallel = parallel_ && parallel_->Pays(with_tangent);
  const bool calibrating = parallel_ && parallel_->Calibrating(with_tangent);
  const double cpu_start = calibrating ? ThreadCpuSeconds() : 0.0;
  if (parallel) {
    parallel_->Evaluate(ctx, with_tangent, scratch, add);
  } else {
    const auto& elements = model_.elements();
    for (size_t e = 0; e < elements.size(); ++e) {
      EvaluateElement(*elements[e], ctx, with_tangent, scratch);
      add(static_cast<int>(e), scratch);
    }
  }
  if (calibrating) parallel_->RecordSerial(with_tangent, ThreadCpuSeconds() - cpu_start);
  assembly_threads_ = parallel ? threads_ : 1;
  if (with_tangent) {
    row_abs_sum_.setZero();
    row_scale_.setZero();
    for (size_t p = 0; p < values_.size(); ++p) {
      const int row = row_index_[p];
      const double a = std::abs(values_[p]);
      row_abs_sum_[row] += a;
      // KLU's own row scaling (klu_scale with scale = 2) in its own form, so that the scaled values are its, bit
      // for bit: the largest |entry| of the row, 1 for an empty row.
      row_scale_[row] = row_scale_[row] > a ? row_scale_[row] : a;
    }
    for (int row = 0; row < n_; ++row) {
      if (row_scale_[row] == 0.0) row_scale_[row] = 1.0;
    }
  }
  timing_.assembly += SecondsSince(start);
}

void SparseSystem::AddElement(int e, const ElementBlocks& blocks, bool with_tangent) {
  const std::vector<int>& u = model_.elements()[e]->unknowns();
  const int m = static_cast<int>(u.size());
  for (int i = 0; i < m; ++i) {
    residual_[u[i]] += blocks.r[i];
    magnitude_[u[i]] += blocks.magnitude[i];
  }
  if (!with_tangent) return;
  // Column by column, as the local block is stored.
  const int* position = scatter_[e].data();
  for (int j = 0; j < m; ++j) {
    const double* column = blocks.J + static_cast<size_t>(j) * blocks.ld;
    for (int i = 0; i < m; ++i) values_[*position++] += column[i];
  }
}

bool SparseSystem::Factorise() {
  klu_common& common = klu_->common;
  // Scaled here as KLU scales the entries it reads (each divided by its row's scale), and the scale kept for the
  // right-hand sides this factorisation will solve: factors and solutions as with KLU's own scaling.
  for (size_t p = 0; p < values_.size(); ++p) scaled_values_[p] = values_[p] / row_scale_[row_index_[p]];
  factor_scale_ = row_scale_;
  if (!klu_->symbolic) {
    klu_->symbolic = klu_analyze(n_, column_start_.data(), row_index_.data(), &common);
    if (!klu_->symbolic) return false;
  }
  if (klu_->numeric) {
    const bool refactored = klu_refactor(column_start_.data(), row_index_.data(), scaled_values_.data(),
                                         klu_->symbolic, klu_->numeric, &common) &&
                            klu_rgrowth(column_start_.data(), row_index_.data(), scaled_values_.data(), klu_->symbolic,
                                        klu_->numeric, &common) &&
                            common.rgrowth >= kRefactorGrowthRatio * klu_->pivoted_growth;
    if (refactored) return true;
    klu_free_numeric(&klu_->numeric, &common);
  }
  klu_->numeric = klu_factor(column_start_.data(), row_index_.data(), scaled_values_.data(), klu_->symbolic, &common);
  if (klu_->numeric == nullptr || common.status != KLU_OK) return false;
  klu_rgrowth(column_start_.data(), row_index_.data(), scaled_values_.data(), klu_->symbolic, klu_->numeric, &common);
  klu_->pivoted_growth = common.rgrowth;
  return true;
}

bool SparseSystem::has_factorisation() const { return klu_->numeric != nullptr; }

int SparseSystem::singular_unknown() const {
  const int column = klu_->common.singular_col;
  return klu_->common.status == KLU_SINGULAR && column >= 0 && column < n_ ? column : -1;
}

bool SparseSystem::Solve(Eigen::VectorXd* dx, bool refactorise) {
  auto start = std::chrono::steady_clock::now();
  const bool factorised = (refactorise || klu_->numeric == nullptr) ? Factorise() : true;
  timing_.factorisation += SecondsSince(start);
  if (!factorised) return false;
  start = std::chrono::steady_clock::now();
  *dx = (-residual_).cwiseQuotient(factor_scale_);
  const bool solved = klu_solve(klu_->symbolic, klu_->numeric, n_, 1, dx->data(), &klu_->common) && dx->allFinite();
  timing_.solve += SecondsSince(start);
  return solved;
}

}  // namespace flexmbd
