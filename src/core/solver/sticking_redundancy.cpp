#include "flexmbd/solver/sticking_redundancy.hpp"

#include <algorithm>
#include <cmath>

#include "constraint_null_space.hpp"
#include "flexmbd/model/model.hpp"

namespace flexmbd {
namespace {
// Step size of the context the rows are taken from [s]: the constraint rows' derivatives by the increments
// depend on the positions only.
constexpr double kAnyStep = 1.0;
}  // namespace

StickingRedundancy::StickingRedundancy(const Model& model)
    : model_(model), builder_(model), trapezoidal_(model.num_nodes()) {
  for (const auto& element : model.elements()) {
    const std::vector<int>& u = element->unknowns();
    if (std::any_of(u.begin(), u.end(), [&](int k) { return !model.is_force_row(k); })) {
      constrained_.push_back(element.get());
    }
  }
}

void StickingRedundancy::CollectRows(const State& state, const std::vector<EffectState>* modes) {
  const int nk = model_.num_kinematic();
  rows_.assign(model_.num_multipliers(), {});
  column_rows_.assign(nk, {});
  Eigen::VectorXd unknowns = Eigen::VectorXd::Zero(model_.num_unknowns());
  unknowns.tail(model_.num_multipliers()) = state.lambda;
  builder_.set_effect_modes(modes);
  const StepContext& ctx = builder_.Dynamic(state, unknowns, kAnyStep, trapezoidal_);
  Eigen::MatrixXd J;
  for (const Element* element : constrained_) {
    const std::vector<int>& u = element->unknowns();
    J.setZero(element->num_local(), element->num_local());
    element->AddTangent(ctx, J);
    for (int i = 0; i < element->num_local(); ++i) {
      if (model_.is_force_row(u[i])) continue;
      for (int j = 0; j < element->num_local(); ++j) {
        if (!model_.is_force_row(u[j]) || J(i, j) == 0.0) continue;
        rows_[u[i] - nk].emplace_back(u[j], J(i, j));
        column_rows_[u[j]].push_back(u[i] - nk);
      }
    }
  }
}

bool StickingRedundancy::Repeats(int row, const std::vector<bool>& kept) const {
  // The rows joined to `row` through shared columns: only they can combine to it.
  std::vector<int> rows, columns;
  std::vector<bool> row_seen(rows_.size(), false), column_seen(column_rows_.size(), false);
  for (const auto& entry : rows_[row]) {
    if (!column_seen[entry.first]) columns.push_back(entry.first);
    column_seen[entry.first] = true;
  }
  for (size_t c = 0; c < columns.size(); ++c) {
    for (int r : column_rows_[columns[c]]) {
      if (r == row || row_seen[r] || !kept[r]) continue;
      row_seen[r] = true;
      rows.push_back(r);
      for (const auto& entry : rows_[r]) {
        if (!column_seen[entry.first]) columns.push_back(entry.first);
        column_seen[entry.first] = true;
      }
    }
  }
  std::vector<int> local(column_rows_.size(), -1);
  for (size_t c = 0; c < columns.size(); ++c) local[columns[c]] = static_cast<int>(c);
  const int n = static_cast<int>(columns.size()), m = static_cast<int>(rows.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(m + 1, n);
  for (int i = 0; i <= m; ++i) {
    for (const auto& entry : rows_[i < m ? rows[i] : row]) B(i, local[entry.first]) += entry.second;
  }
  return ConstraintNullSpace::RankOf(B) == ConstraintNullSpace::RankOf(B.topRows(m));
}

void StickingRedundancy::Mark(const State& state, std::vector<EffectState>* modes) {
  // A joint that stayed stuck over the step before with its row in (a steady stick) keeps it: the rows it held
  // the loop with have not moved since. The others sticking in `modes` are tested: the step that starts sticking
  // (or the run's first), and every step after one whose row was left out.
  auto sticking = [&](const FrictionEffect* friction) {
    return friction->has_sticking_row() && (*modes)[friction->slot()].mode == FrictionEffect::kSticking;
  };
  auto steady = [&](const FrictionEffect* friction) {
    return !std::isnan(state.effects[friction->slot()].steady_force);
  };
  bool any_to_test = false;
  for (const FrictionEffect* friction : model_.friction_effects()) {
    (*modes)[friction->slot()].held_by_constraints = false;
    any_to_test = any_to_test || (sticking(friction) && !steady(friction));
  }
  if (!any_to_test) return;
  CollectRows(state, modes);
  // Every active row but the sticking ones to test, which join one by one in the model's order unless they repeat.
  std::vector<bool> kept(rows_.size());
  for (size_t k = 0; k < rows_.size(); ++k) kept[k] = !rows_[k].empty();
  for (const FrictionEffect* friction : model_.friction_effects()) {
    if (sticking(friction) && !steady(friction)) kept[friction->stick_multiplier()] = false;
  }
  for (const FrictionEffect* friction : model_.friction_effects()) {
    const int row = friction->stick_multiplier();
    if (!sticking(friction) || steady(friction) || rows_[row].empty()) continue;
    EffectState& effect = (*modes)[friction->slot()];
    effect.held_by_constraints = Repeats(row, kept);
    kept[row] = !effect.held_by_constraints;
  }
}

}  // namespace flexmbd
