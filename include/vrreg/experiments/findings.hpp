// SPDX-License-Identifier: Apache-2.0
#pragma once
// The paper's findings (sections 5.1, 5.2) checked on a reproduction:
// gamma(A2) > gamma(A1); corrected RMS_T falls with d (Spearman >= 0.9, Figure 7); N_bad(d_min) <
// N_bad(d_max) (Figure 8); Strategies 2 and 3 beat Strategy 1 wherever configurations were
// switched; Strategy 3 has the largest gamma; corrected RMS_T is uniform over the configurations
// for Strategies 2 and 3 (spread < 30 % of the mean) and not for Strategy 1 (Table 2).
#include <string>
#include <vector>

#include "vrreg/experiments/reproduction.hpp"

namespace vrreg::experiments {

/// Thresholds of the findings.
inline constexpr double kSpearmanThreshold = 0.9;       ///< cor RMS_T vs d
inline constexpr double kUniformSpreadFraction = 0.30;  ///< (max - min) / mean over configurations
inline constexpr double kFindingAcceptanceRate = 0.80;  ///< share of seeds a finding must hold on

/// One finding on one seed.
struct Finding {
  std::string id{};         ///< stable key, e.g. "gamma_a2_above_a1"
  std::string statement{};  ///< what the paper found, e.g. "gamma(A2) > gamma(A1)"
  double value = 0.0;      ///< the number compared with the threshold (see `detail`)
  std::string detail{};    ///< the value in words, e.g. "gamma(A2) - gamma(A1) = 12.8 points"
  bool evaluated = false;  ///< false when the datasets it needs were not run
  bool met = false;
};

/// The six findings on `r` (those whose datasets were not run: evaluated = false, not met).
std::vector<Finding> evaluate_findings(const Reproduction& r);

/// (max - min) / mean of corrected RMS_T over the configurations of `table` for `strategy`.
double cor_rms_t_relative_spread(const Table2& table, int strategy);

/// One finding over several seeds.
struct FindingRate {
  std::string id{};
  std::string statement{};
  int n_met = 0;
  int n_evaluated = 0;
  std::vector<double> values{};  ///< per seed, in seed order
  std::vector<bool> met{};       ///< per seed
  /// n_met / n_evaluated (0 when none was evaluated).
  [[nodiscard]] double rate() const;
  /// Met on >= 80 % of the seeds evaluated: one unlucky simulated robot does not fail a finding.
  [[nodiscard]] bool accepted() const;
};

/// Rates per finding over `per_seed` (each the output of evaluate_findings, same order of ids).
/// Throws InputError when the lists do not line up.
std::vector<FindingRate> finding_rates(const std::vector<std::vector<Finding>>& per_seed);

}  // namespace vrreg::experiments
