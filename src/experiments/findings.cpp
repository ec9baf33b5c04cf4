// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/findings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "vrreg/core/check.hpp"
#include "vrreg/experiments/statistics.hpp"

namespace vrreg::experiments {
namespace {

Finding make(const char* id, const char* statement) {
  Finding f;
  f.id = id;
  f.statement = statement;
  f.value = std::numeric_limits<double>::quiet_NaN();
  return f;
}

Finding gamma_a2_above_a1(const Reproduction& r) {
  Finding f = make("gamma_a2_above_a1", "gamma(A2) > gamma(A1) (Table 1)");
  if (!r.a1 || !r.a2) return f;
  const double g1 = 100.0 * r.a1->figures.gamma, g2 = 100.0 * r.a2->figures.gamma;
  f.evaluated = true;
  f.value = g2 - g1;
  f.met = g2 > g1;
  f.detail = fmt::format("gamma(A2) {:.1f} % vs gamma(A1) {:.1f} %", g2, g1);
  return f;
}

Finding cor_falls_with_d(const Reproduction& r) {
  Finding f = make("cor_rms_t_falls_with_d",
                   "corrected RMS_T falls as d falls: Spearman(d, cor RMS_T) >= 0.9 (Figure 7)");
  if (!r.b || r.b->steps.size() < 2) return f;
  std::vector<double> d, cor;
  for (const SweepStep& s : r.b->steps) {
    d.push_back(s.d_m);
    cor.push_back(s.cor_rms_t_m);
  }
  f.evaluated = true;
  f.value = spearman_rank_correlation(d, cor);
  f.met = f.value >= kSpearmanThreshold;  // false for NaN
  f.detail = fmt::format("Spearman {:.3f} over {} cube sizes", f.value, d.size());
  return f;
}

Finding fewer_bad_at_d_min(const Reproduction& r) {
  Finding f = make("n_bad_fewer_at_d_min", "N_bad(d_min) < N_bad(d_max) (Figure 8)");
  if (!r.b || r.b->steps.empty()) return f;
  const int lo = r.b->at_d_min().n_bad, hi = r.b->at_d_max().n_bad;
  f.evaluated = true;
  f.value = hi - lo;
  f.met = lo < hi;
  f.detail = fmt::format("N_bad {} at d_min vs {} at d_max", lo, hi);
  return f;
}

Finding strategies_beat_1(const Reproduction& r) {
  Finding f = make("strategies_2_3_beat_1",
                   "for every configuration with switched locations, Strategy 2's and 3's "
                   "corrected RMS_T < Strategy 1's (Table 2)");
  if (!r.table2) return f;
  const Table2& t = *r.table2;
  f.evaluated = true;
  double worst = -std::numeric_limits<double>::infinity();
  std::string configs;
  for (const int m : t.configs) {
    if (!t.switched(m)) continue;
    const double s1 = t.at(m, 1).figures.cor_rms_t_m;
    const double s23 = std::max(t.at(m, 2).figures.cor_rms_t_m, t.at(m, 3).figures.cor_rms_t_m);
    worst = std::max(worst, s23 / s1);
    configs += (configs.empty() ? "" : ", ") + std::to_string(m);
  }
  if (configs.empty()) {
    f.detail = "no configuration was switched: nothing to compare";
    return f;
  }
  f.value = worst;
  f.met = worst < 1.0;
  f.detail =
      fmt::format("configurations {}: max(S2, S3) / S1 = {:.2f} at worst", configs.c_str(), worst);
  return f;
}

Finding strategy3_largest_gamma(const Reproduction& r) {
  Finding f = make("strategy3_largest_gamma",
                   "Strategy 3 has the largest gamma, in every configuration (Table 2)");
  if (!r.table2 || r.table2->configs.empty()) return f;
  const Table2& t = *r.table2;
  f.evaluated = true;
  double margin = std::numeric_limits<double>::infinity();
  for (const int m : t.configs) {
    const double g3 = t.at(m, 3).figures.gamma;
    const double g12 = std::max(t.at(m, 1).figures.gamma, t.at(m, 2).figures.gamma);
    margin = std::min(margin, 100.0 * (g3 - g12));
  }
  f.value = margin;
  f.met = margin > 0.0;
  f.detail = fmt::format("gamma(S3) - max(gamma(S1), gamma(S2)) >= {:.1f} points", margin);
  return f;
}

Finding uniform_over_configurations(const Reproduction& r) {
  Finding f = make("cor_rms_t_uniform_s2_s3",
                   "spread (max - min) of corrected RMS_T over the configurations < 30 % of its "
                   "mean for Strategies 2 and 3, and larger for Strategy 1 (Table 2)");
  if (!r.table2 || r.table2->configs.size() < 2) return f;
  const double s1 = cor_rms_t_relative_spread(*r.table2, 1);
  const double s2 = cor_rms_t_relative_spread(*r.table2, 2);
  const double s3 = cor_rms_t_relative_spread(*r.table2, 3);
  f.evaluated = true;
  f.value = std::max(s2, s3);
  f.met =
      s2 < kUniformSpreadFraction && s3 < kUniformSpreadFraction && s1 >= kUniformSpreadFraction;
  f.detail = fmt::format("spread / mean: S1 {:.0f} %, S2 {:.0f} %, S3 {:.0f} %", 100 * s1, 100 * s2,
                         100 * s3);
  return f;
}

}  // namespace

double cor_rms_t_relative_spread(const Table2& table, int strategy) {
  std::vector<double> cor;
  for (const int m : table.configs) cor.push_back(table.at(m, strategy).figures.cor_rms_t_m);
  VRREG_THROW_UNLESS(!cor.empty(), "Table 2 has no configurations");
  const auto [lo, hi] = std::minmax_element(cor.begin(), cor.end());
  return (*hi - *lo) / mean_sd(cor).mean;
}

std::vector<Finding> evaluate_findings(const Reproduction& r) {
  return {gamma_a2_above_a1(r), cor_falls_with_d(r),        fewer_bad_at_d_min(r),
          strategies_beat_1(r), strategy3_largest_gamma(r), uniform_over_configurations(r)};
}

double FindingRate::rate() const {
  return n_evaluated == 0 ? 0.0 : static_cast<double>(n_met) / static_cast<double>(n_evaluated);
}

bool FindingRate::accepted() const {
  return n_evaluated > 0 && rate() >= kFindingAcceptanceRate - 1e-12;
}

std::vector<FindingRate> finding_rates(const std::vector<std::vector<Finding>>& per_seed) {
  std::vector<FindingRate> out;
  if (per_seed.empty()) return out;
  for (const Finding& f : per_seed.front()) out.push_back({f.id, f.statement, 0, 0, {}, {}});
  for (const std::vector<Finding>& seed : per_seed) {
    VRREG_THROW_UNLESS(seed.size() == out.size(),
                       "finding rates: " << seed.size() << " findings, expected " << out.size());
    for (std::size_t k = 0; k < seed.size(); ++k) {
      VRREG_THROW_UNLESS(seed[k].id == out[k].id, "finding rates: '" << seed[k].id << "' where '"
                                                                     << out[k].id
                                                                     << "' was expected");
      out[k].values.push_back(seed[k].value);
      out[k].met.push_back(seed[k].met);
      if (!seed[k].evaluated) continue;
      ++out[k].n_evaluated;
      out[k].n_met += seed[k].met ? 1 : 0;
    }
  }
  return out;
}

}  // namespace vrreg::experiments
