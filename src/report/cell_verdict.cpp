// SPDX-License-Identifier: Apache-2.0
// The cell report's verdict in words: is RRBC expected to help (rho against 2.5, section 5.1),
// did it (gamma), where did it fail (N_bad), what was left out (flagged targets).
#include <fmt/format.h>

#include <cstdio>
#include <string>

#include "vrreg/metrics/noise.hpp"
#include "vrreg/report/cell_report.hpp"

namespace vrreg::report {
namespace {

ReportVerdict rho_verdict(const CellAnalysis& a) {
  const double sl = a.rigid_body.sigma_l_m * 1e3;
  if (!a.noise.rho) {
    return {Tone::kInfo,
            fmt::format("ρ unknown: σ_L = {:.3f} mm, but the fiducials have no repeat readings to "
                        "estimate the sensor noise and no robot repeatability σ_rep was given, "
                        "so ρ = σ_L / σ_noise cannot be judged against 2.5.",
                        sl)};
  }
  const double noise = *a.noise.sigma_noise_m * 1e3;
  if (*a.noise.rho > kRhoThreshold) {
    return {Tone::kGood,
            fmt::format("ρ = σ_L / σ_noise = {:.3f} / {:.3f} mm = {:.2f} > 2.5: the deviation from "
                        "a rigid body is mostly systematic robot error, which RRBC can remove.",
                        sl, noise, *a.noise.rho)};
  }
  return {
      Tone::kWarn,
      fmt::format("ρ = σ_L / σ_noise = {:.3f} / {:.3f} mm = {:.2f} ≤ 2.5: the deviation from a "
                  "rigid body is close to the noise level, so RRBC is not expected to help; a gain "
                  "below may not hold on new targets.",
                  sl, noise, *a.noise.rho)};
}

}  // namespace

std::vector<ReportVerdict> cell_verdict(const CellReportInput& input, const CellAnalysis& a) {
  std::vector<ReportVerdict> v;
  v.push_back(rho_verdict(a));
  const ImprovementSummary& s = a.summary;
  const double unc = s.unc_rms_t_m * 1e3;
  const double cor = s.cor_rms_t_m * 1e3;
  const int n_flagged = input.evaluation.correction.n_flagged;
  const std::string flagged_text =
      std::to_string(n_flagged) + " of " + std::to_string(input.evaluation.n_targets()) +
      fmt::format(
          " targets could not be corrected (no fiducials around them, or too few "
          "fiducials); they are left uncorrected (RMS_T {:.3f} mm as registered) and "
          "are not in the figures above.",
          input.evaluation.flagged_rms_t_m * 1e3);
  if (s.n_targets == 0) {
    v.push_back({Tone::kWarn, n_flagged > 0 ? flagged_text : "No targets were evaluated."});
    return v;
  }
  const std::string n = std::to_string(s.n_targets);
  if (s.gamma > 0.0) {
    v.push_back(
        {Tone::kGood, fmt::format("RRBC lowered RMS_T from {:.3f} mm to {:.3f} mm: γ = {:.0f} %",
                                  unc, cor, 100.0 * s.gamma) +
                          " over " + n + " targets."});
  } else {
    v.push_back(
        {Tone::kBad,
         fmt::format("RRBC did not lower RMS_T ({:.3f} mm uncorrected, {:.3f} mm corrected, γ = "
                     "{:.0f} %)",
                     unc, cor, 100.0 * s.gamma) +
             " over " + n + " targets: do not use its corrections for this cell."});
  }
  if (s.n_bad == 0) {
    v.push_back({Tone::kGood, "N_bad = 0: RRBC made no target worse."});
  } else {
    int worst = s.bad_targets.front();
    for (int k : s.bad_targets) {
      if (a.cor_tre_m[k] - a.unc_tre_m[k] > a.cor_tre_m[worst] - a.unc_tre_m[worst]) worst = k;
    }
    const auto w = static_cast<std::size_t>(worst);
    const bool few = 10 * s.n_bad <= s.n_targets;
    v.push_back(
        {few ? Tone::kInfo : Tone::kWarn,
         "N_bad = " + std::to_string(s.n_bad) + " of " + n +
             " targets got worse with RRBC (the most: " + a.labels[w] +
             fmt::format(", +{:.3f} mm). ", (a.cor_tre_m[worst] - a.unc_tre_m[worst]) * 1e3) +
             "Where: " + a.where_bad + "."});
  }
  if (n_flagged > 0) v.push_back({Tone::kWarn, flagged_text});
  // The largest TRE among the corrected targets (a flagged one's is not a corrected TRE).
  Eigen::Index worst = -1;
  for (Eigen::Index k = 0; k < a.cor_tre_m.size(); ++k) {
    if (!is_corrected(input.evaluation.correction.stencils[static_cast<std::size_t>(k)].status))
      continue;
    if (worst < 0 || a.cor_tre_m[k] > a.cor_tre_m[worst]) worst = k;
  }
  if (worst >= 0) {
    v.push_back(
        {Tone::kInfo, fmt::format("Largest corrected TRE: {:.3f} mm", a.cor_tre_m[worst] * 1e3) +
                          " at " + a.labels[static_cast<std::size_t>(worst)] +
                          fmt::format(" (uncorrected {:.3f} mm).", a.unc_tre_m[worst] * 1e3)});
  }
  return v;
}

}  // namespace vrreg::report
