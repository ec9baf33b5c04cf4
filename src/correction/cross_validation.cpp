// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/cross_validation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "method_support.hpp"
#include "point_index.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/progress.hpp"
#include "vrreg/core/random.hpp"

namespace vrreg {
namespace {

// A method that cannot predict this share of held-out fiducials (a lattice with too many holes)
// is not compared: the common subset would be too small to judge the others.
constexpr double kMinPredictedShare = 0.5;

// Fiducials closer than this fraction of the layout's spacing are one fold unit.
constexpr double kClusterFraction = 1.0 / 3.0;

// How many of the fiducials `use(j)` picks each fold unit holds.
template <class Use>
std::vector<int> unit_counts(const std::vector<Eigen::Index>& unit_of, Use use) {
  const std::size_t units =
      unit_of.empty() ? 0
                      : static_cast<std::size_t>(*std::max_element(unit_of.begin(), unit_of.end()) + 1);
  std::vector<int> count(units, 0);
  for (std::size_t j = 0; j < unit_of.size(); ++j) {
    if (use(static_cast<Eigen::Index>(j))) ++count[static_cast<std::size_t>(unit_of[j])];
  }
  return count;
}

// Which held-out set each fiducial is in (-1: never held out): its fold, or in a large cell
// one sample of about kLargeCellHeldOut fiducials, every s-th fold unit of fold 0 (a seeded
// random share of the units, so spread over the volume), predicted by one model fitted on all
// the rest. Five refits on 4/5 of 10^5 fiducials, each predicting 2 10^4 of them with a local
// model, cost minutes; one refit on 98 % of them predicting 2 000 costs seconds, with the same
// training density.
std::vector<int> held_out_groups(Eigen::Index n, const std::vector<int>& fold_of,
                                 const std::vector<Eigen::Index>& unit_of, int folds) {
  std::vector<int> group(fold_of);
  if (n <= kLargeCellFiducials || folds < 1) return group;
  std::vector<Eigen::Index> units;  // fold 0's units, in order
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto u = static_cast<std::size_t>(unit_of[static_cast<std::size_t>(j)]);
    if (fold_of[static_cast<std::size_t>(j)] == 0 && seen[u] == 0) {
      seen[u] = 1;
      units.push_back(static_cast<Eigen::Index>(u));
    }
  }
  const std::size_t stride = std::max<std::size_t>(
      1, (units.size() + static_cast<std::size_t>(kLargeCellHeldOut) - 1) /
             static_cast<std::size_t>(kLargeCellHeldOut));
  std::vector<char> chosen(static_cast<std::size_t>(n), 0);
  for (std::size_t k = 0; k < units.size(); k += stride)
    chosen[static_cast<std::size_t>(units[k])] = 1;
  for (Eigen::Index j = 0; j < n; ++j) {
    group[static_cast<std::size_t>(j)] =
        chosen[static_cast<std::size_t>(unit_of[static_cast<std::size_t>(j)])] != 0 ? 0 : -1;
  }
  return group;
}

}  // namespace

MethodPredictions detail::predict_held_out(const FittedMethod& fitted,
                                            const CorrectorData& held_out) {
  const Eigen::Index n = held_out.size();
  MethodPredictions p;
  p.corrections_sensor_m.setZero(3, n);
  p.stencils.resize(static_cast<std::size_t>(n));
  if (fitted.has_own_sd()) p.sd_m.resize(n);
  const MethodQuery query{held_out.registered_robot_m, held_out.fiducials_robot_m,
                          held_out.joints_rad, held_out.sequence};
  fitted.check_query(query);
  const Eigen::Index block = std::max<Eigen::Index>(fitted.block_size(), 1);
  for (Eigen::Index begin = 0; begin < n; begin += block) {
    fitted.predict(query, begin, std::min(n, begin + block), p);
  }
  return p;
}


std::vector<Eigen::Index> fold_units(const ConstPoints3Ref& positions_m) {
  const Eigen::Index n = positions_m.cols();
  std::vector<Eigen::Index> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), Eigen::Index{0});
  if (n >= 2) {
    const double link_m = kClusterFraction * detail::volume_spacing_m(positions_m);
    if (link_m > 0.0) {
      const auto find = [&](Eigen::Index j) {
        while (parent[static_cast<std::size_t>(j)] != j) {
          parent[static_cast<std::size_t>(j)] =
              parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(j)])];
          j = parent[static_cast<std::size_t>(j)];
        }
        return j;
      };
      const detail::PointIndex index(positions_m);
      for (Eigen::Index j = 0; j < n; ++j) {
        for (const Eigen::Index k : index.within(positions_m.col(j), link_m)) {
          const Eigen::Index a = find(j);
          const Eigen::Index b = find(k);
          if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
        }
      }
      for (Eigen::Index j = 0; j < n; ++j) parent[static_cast<std::size_t>(j)] = find(j);
    }
  }
  // Units numbered in order of their first fiducial: on a layout without clusters, unit j is
  // fiducial j.
  std::vector<Eigen::Index> number(static_cast<std::size_t>(n), -1);
  std::vector<Eigen::Index> out(static_cast<std::size_t>(n));
  Eigen::Index next = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    Eigen::Index& u = number[static_cast<std::size_t>(parent[static_cast<std::size_t>(j)])];
    if (u < 0) u = next++;
    out[static_cast<std::size_t>(j)] = u;
  }
  return out;
}

std::vector<int> assign_folds(const std::vector<Eigen::Index>& unit_of, int folds,
                              std::uint64_t seed) {
  VRREG_THROW_UNLESS(folds >= 1, "cross-validation needs at least 1 fold, got " << folds);
  const std::size_t units =
      unit_of.empty() ? 0
                      : static_cast<std::size_t>(*std::max_element(unit_of.begin(), unit_of.end()) + 1);
  std::vector<std::size_t> order(units);
  std::iota(order.begin(), order.end(), std::size_t{0});
  Random rng(seed);
  for (std::size_t i = order.size(); i > 1; --i) {  // Fisher-Yates with the project's generator
    std::swap(order[i - 1], order[static_cast<std::size_t>(rng.below(i))]);
  }
  std::vector<int> fold_of_unit(units);
  for (std::size_t i = 0; i < order.size(); ++i)
    fold_of_unit[order[i]] = static_cast<int>(i % static_cast<std::size_t>(folds));
  std::vector<int> out(unit_of.size());
  for (std::size_t j = 0; j < unit_of.size(); ++j)
    out[j] = fold_of_unit[static_cast<std::size_t>(unit_of[j])];
  return out;
}

CrossValidationRow cross_validate(InterpolationMethod method, const CorrectorData& data,
                                  const MethodSettings& settings, const std::vector<int>& fold_of,
                                  const std::vector<Eigen::Index>& unit_of, int folds,
                                  FitOutcome* full) {
  VRREG_THROW_UNLESS(fold_of.size() == static_cast<std::size_t>(data.size()) &&
                         unit_of.size() == fold_of.size(),
                     "cross-validation: " << fold_of.size() << " folds for " << data.size()
                                          << " fiducials");
  CrossValidationRow row;
  row.method = method;
  const CorrectionMethod& m = correction_method(method);
  // The paper's stencils stand in the table beside the field models on the same terms.
  if (!m.field_model && data.size() < detail::kMinFieldModelFiducials) {
    row.note = "fewer than 12 fiducials";
    return row;
  }
  if (m.unavailable != nullptr) row.note = m.unavailable(data, settings);
  if (!row.note.empty()) return row;
  const auto start = std::chrono::steady_clock::now();
  const int groups = data.size() > kLargeCellFiducials ? 1 : folds;
  ProgressStage progress("cross-validating " + std::string(to_string(method)), 1 + groups);
  FitOutcome all = m.fit(data, settings);
  progress.advance();
  if (!all.fitted) {
    row.note = all.not_applicable;
    return row;
  }
  row.squared_error_m2.setConstant(data.size(), std::numeric_limits<double>::quiet_NaN());
  Points3 squared_axis(3, data.size());
  std::vector<Eigen::Index> order;  // fiducials in the order they were predicted
  const std::vector<int> held_out_in = held_out_groups(data.size(), fold_of, unit_of, folds);
  Eigen::Index n_tested = 0;
  for (int f = 0; f < groups; ++f) {
    std::vector<Eigen::Index> train;
    std::vector<Eigen::Index> test;
    for (Eigen::Index j = 0; j < data.size(); ++j)
      (held_out_in[static_cast<std::size_t>(j)] == f ? test : train).push_back(j);
    progress.advance();
    if (test.empty()) continue;
    n_tested += static_cast<Eigen::Index>(test.size());
    const CorrectorData trained = data.subset(train);
    const FitOutcome model = all.fitted->refit(trained, settings);
    if (!model.fitted) continue;  // this fold's training set cannot carry the method
    const CorrectorData held_out = data.subset(test);
    const MethodPredictions p = detail::predict_held_out(*model.fitted, held_out);
    const Eigen::Vector3d lo_m = trained.fiducials_robot_m.rowwise().minCoeff();
    const Eigen::Vector3d hi_m = trained.fiducials_robot_m.rowwise().maxCoeff();
    for (std::size_t i = 0; i < test.size(); ++i) {
      if (p.stencils[i].status != StencilStatus::kOk) {
        // A fiducial on the layout's face that registers just beyond it (a sensor's scale
        // error) is outside what the training fiducials cover: not a failure of the method.
        const auto c = static_cast<Eigen::Index>(i);
        const Eigen::Vector3d y = held_out.registered_robot_m.col(c);
        if ((y.array() < lo_m.array()).any() || (y.array() > hi_m.array()).any())
          ++row.n_outside_training;
        continue;
      }
      const auto c = static_cast<Eigen::Index>(i);
      squared_axis.col(test[i]) =
          (p.corrections_sensor_m.col(c) - held_out.corrections_sensor_m.col(c)).cwiseAbs2();
      row.squared_error_m2(test[i]) = squared_axis.col(test[i]).sum();
      order.push_back(test[i]);
      ++row.n_predicted;
    }
  }
  // Each fold unit weighs as one fiducial: a cluster's errors are averaged first (on a layout
  // without clusters, the plain RMS over the predicted fiducials).
  const std::vector<int> count = unit_counts(unit_of, [&](Eigen::Index j) {
    return !std::isnan(row.squared_error_m2(j));
  });
  Eigen::Vector3d sum_sq = Eigen::Vector3d::Zero();
  for (const Eigen::Index j : order) {
    const int c = count[static_cast<std::size_t>(unit_of[static_cast<std::size_t>(j)])];
    sum_sq += c == 1 ? Eigen::Vector3d(squared_axis.col(j))
                     : Eigen::Vector3d(squared_axis.col(j) / static_cast<double>(c));
  }
  const auto units_predicted = std::count_if(count.begin(), count.end(), [](int c) { return c > 0; });
  if (full != nullptr) *full = std::move(all);
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Eigen::Index n_judged = n_tested - row.n_outside_training;
  if (static_cast<double>(row.n_predicted) < kMinPredictedShare * static_cast<double>(n_judged)) {
    row.note = "predicted only " + std::to_string(row.n_predicted) + " of " +
               std::to_string(n_judged) + " held-out fiducials inside the training fiducials' box";
    if (full != nullptr) *full = FitOutcome{};
    return row;
  }
  row.rms_axis_m = (sum_sq / static_cast<double>(units_predicted)).cwiseSqrt();
  row.rms_m = row.rms_axis_m.norm();
  row.applicable = true;
  return row;
}

std::vector<InterpolationMethod> auto_candidates() {
  return {InterpolationMethod::kScattered, InterpolationMethod::kTrilinear,
          InterpolationMethod::kRbf, InterpolationMethod::kKriging, InterpolationMethod::kJoint};
}

CrossValidation choose_by_cross_validation(const CorrectorData& data,
                                           const MethodSettings& settings, int folds,
                                           std::uint64_t seed, FitOutcome* chosen) {
  VRREG_THROW_UNLESS(folds >= 2 && data.size() >= 2 * folds,
                     folds << "-fold cross-validation needs at least " << 2 * folds
                           << " fiducials, got " << data.size());
  CrossValidation out;
  out.folds = data.size() > kLargeCellFiducials ? 1 : folds;
  out.seed = seed;
  const std::vector<Eigen::Index> units = fold_units(data.fiducials_robot_m);
  out.n_units = units.empty() ? 0 : *std::max_element(units.begin(), units.end()) + 1;
  const std::vector<int> fold_of = assign_folds(units, folds, seed);
  std::vector<FitOutcome> fitted;
  for (const InterpolationMethod m : auto_candidates()) {
    fitted.emplace_back();
    out.rows.push_back(cross_validate(m, data, settings, fold_of, units, folds, &fitted.back()));
  }
  // Ranked on every fiducial some method predicted, each method's misses among them at their
  // uncorrected error (what a target there gets from it). Ranking only on the fiducials every
  // method predicted (the hull of the fold's training fiducials) favoured the models that are
  // good in the interior: on real cells kriging over a joint model 1.6x better at the targets.
  std::vector<char> ranked(static_cast<std::size_t>(data.size()), 0);
  for (const CrossValidationRow& row : out.rows) {
    if (!row.applicable) continue;
    for (Eigen::Index j = 0; j < data.size(); ++j) {
      if (!std::isnan(row.squared_error_m2(j))) ranked[static_cast<std::size_t>(j)] = 1;
    }
  }
  out.n_ranked = std::count(ranked.begin(), ranked.end(), char{1});
  const std::vector<int> count =
      unit_counts(units, [&](Eigen::Index j) { return ranked[static_cast<std::size_t>(j)] != 0; });
  const auto ranked_units = std::count_if(count.begin(), count.end(), [](int c) { return c > 0; });
  const CrossValidationRow* best = nullptr;
  for (CrossValidationRow& row : out.rows) {
    if (!row.applicable || out.n_ranked == 0) continue;
    double sum = 0.0;
    for (Eigen::Index j = 0; j < data.size(); ++j) {
      if (ranked[static_cast<std::size_t>(j)] == 0) continue;
      const double e = std::isnan(row.squared_error_m2(j))
                           ? data.corrections_sensor_m.col(j).squaredNorm()
                           : row.squared_error_m2(j);
      const int c = count[static_cast<std::size_t>(units[static_cast<std::size_t>(j)])];
      sum += c == 1 ? e : e / static_cast<double>(c);
    }
    row.rms_ranked_m = std::sqrt(sum / static_cast<double>(ranked_units));
    if (best == nullptr || row.rms_ranked_m < best->rms_ranked_m) best = &row;
  }
  VRREG_THROW_UNLESS(best != nullptr,
                     "no interpolation method could be cross-validated on these fiducials");
  out.chosen = best->method;
  if (chosen != nullptr) {
    *chosen = std::move(fitted[static_cast<std::size_t>(best - out.rows.data())]);
  }
  return out;
}

}  // namespace vrreg
