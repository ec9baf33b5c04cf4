#include "cross_validation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"

namespace vrreg::pipeline_detail {
namespace {

// A method that cannot predict this share of held-out fiducials (a lattice with too many holes)
// is not compared: the common subset would be too small to judge the others.
constexpr double kMinPredictedShare = 0.5;

}  // namespace

std::vector<int> assign_folds(Eigen::Index n, int folds, std::uint64_t seed) {
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  Random rng(seed);
  for (std::size_t i = order.size(); i > 1; --i) {  // Fisher-Yates with the project's generator
    std::swap(order[i - 1], order[static_cast<std::size_t>(rng.below(i))]);
  }
  std::vector<int> fold_of(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < order.size(); ++i)
    fold_of[static_cast<std::size_t>(order[i])] = static_cast<int>(i % static_cast<std::size_t>(folds));
  return fold_of;
}

CrossValidationRow cross_validate(InterpolationMethod method, const FieldData& data,
                                  const std::vector<int>& fold_of, int folds,
                                  std::unique_ptr<FieldModel>* full) {
  CrossValidationRow row;
  row.method = method;
  row.note = field_model_unavailable(method, data);
  if (!row.note.empty()) return row;
  const auto start = std::chrono::steady_clock::now();
  Eigen::Vector3d sum_sq = Eigen::Vector3d::Zero();
  row.squared_error_m2.setConstant(data.size(), std::numeric_limits<double>::quiet_NaN());
  try {
    std::unique_ptr<FieldModel> model_all = fit_field_model(method, data);
    for (int f = 0; f < folds; ++f) {
      std::vector<Eigen::Index> train;
      std::vector<Eigen::Index> test;
      for (Eigen::Index j = 0; j < data.size(); ++j)
        (fold_of[static_cast<std::size_t>(j)] == f ? test : train).push_back(j);
      if (test.empty()) continue;
      const auto model = model_all->refit(data.subset(train));
      const FieldData held_out = data.subset(test);
      const FieldPredictions p =
          model->predict(FieldQuery{held_out.registered_robot_m, held_out.joints_rad});
      for (std::size_t i = 0; i < test.size(); ++i) {
        if (p.ok[i] == 0) continue;
        const auto c = static_cast<Eigen::Index>(i);
        const Eigen::Vector3d sq =
            (p.corrections_sensor_m.col(c) - held_out.corrections_sensor_m.col(c)).cwiseAbs2();
        sum_sq += sq;
        row.squared_error_m2(test[i]) = sq.sum();
        ++row.n_predicted;
      }
    }
    if (full != nullptr) *full = std::move(model_all);
  } catch (const InputError& e) {
    row.note = e.what();
    return row;
  }
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (static_cast<double>(row.n_predicted) < kMinPredictedShare * static_cast<double>(data.size())) {
    row.note = "predicted only " + std::to_string(row.n_predicted) + " of " +
               std::to_string(data.size()) + " held-out fiducials";
    return row;
  }
  row.rms_axis_m = (sum_sq / static_cast<double>(row.n_predicted)).cwiseSqrt();
  row.rms_m = row.rms_axis_m.norm();
  row.applicable = true;
  return row;
}

std::vector<InterpolationMethod> auto_candidates() {
  return {InterpolationMethod::kScattered, InterpolationMethod::kTrilinear,
          InterpolationMethod::kRbf, InterpolationMethod::kKriging, InterpolationMethod::kJoint};
}

CrossValidation choose_by_cross_validation(const FieldData& data, int folds, std::uint64_t seed,
                                           std::unique_ptr<FieldModel>* chosen_model) {
  VRREG_THROW_UNLESS(folds >= 2 && data.size() >= 2 * folds,
                     folds << "-fold cross-validation needs at least " << 2 * folds
                           << " fiducials, got " << data.size());
  CrossValidation out;
  out.folds = folds;
  out.seed = seed;
  const std::vector<int> fold_of = assign_folds(data.size(), folds, seed);
  std::vector<std::unique_ptr<FieldModel>> fitted;
  for (const InterpolationMethod m : auto_candidates()) {
    fitted.emplace_back();
    out.rows.push_back(cross_validate(m, data, fold_of, folds, &fitted.back()));
  }
  std::vector<char> common(static_cast<std::size_t>(data.size()), 1);
  for (const CrossValidationRow& row : out.rows) {
    if (!row.applicable) continue;
    for (Eigen::Index j = 0; j < data.size(); ++j) {
      if (std::isnan(row.squared_error_m2(j))) common[static_cast<std::size_t>(j)] = 0;
    }
  }
  out.n_common = std::count(common.begin(), common.end(), char{1});
  const CrossValidationRow* best = nullptr;
  for (CrossValidationRow& row : out.rows) {
    if (!row.applicable || out.n_common == 0) continue;
    double sum = 0.0;
    for (Eigen::Index j = 0; j < data.size(); ++j) {
      if (common[static_cast<std::size_t>(j)] != 0) sum += row.squared_error_m2(j);
    }
    row.rms_common_m = std::sqrt(sum / static_cast<double>(out.n_common));
    if (best == nullptr || row.rms_common_m < best->rms_common_m) best = &row;
  }
  VRREG_THROW_UNLESS(best != nullptr,
                     "no interpolation method could be cross-validated on these fiducials");
  out.chosen = best->method;
  if (chosen_model != nullptr) {
    *chosen_model = std::move(fitted[static_cast<std::size_t>(best - out.rows.data())]);
  }
  return out;
}

}  // namespace vrreg::pipeline_detail
