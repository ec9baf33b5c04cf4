// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/uncertainty_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "vrreg/core/check.hpp"

namespace vrreg {

PredictedSdSummary summarize_predicted_sd(const Eigen::Ref<const Eigen::VectorXd>& sd_m) {
  std::vector<double> finite;
  for (Eigen::Index i = 0; i < sd_m.size(); ++i) {
    if (std::isfinite(sd_m(i))) finite.push_back(sd_m(i));
  }
  PredictedSdSummary out;
  if (finite.empty()) return out;
  std::sort(finite.begin(), finite.end());
  const std::size_t n = finite.size();
  out.n = static_cast<Eigen::Index>(n);
  out.median_m = n % 2 == 1 ? finite[n / 2] : 0.5 * (finite[n / 2 - 1] + finite[n / 2]);
  out.max_m = finite.back();
  return out;
}

UncertaintyCalibration uncertainty_calibration(const Eigen::Ref<const Eigen::VectorXd>& tre_m,
                                               const Eigen::Ref<const Eigen::VectorXd>& sd_m) {
  UncertaintyCalibration out;
  if (sd_m.size() == 0) return out;
  VRREG_THROW_UNLESS(sd_m.size() == tre_m.size(),
                     "got " << sd_m.size() << " predicted sd for " << tre_m.size() << " TRE");
  double sum_sq = 0.0;
  Eigen::Index within = 0;
  for (Eigen::Index i = 0; i < tre_m.size(); ++i) {
    if (!(std::isfinite(sd_m(i)) && sd_m(i) > 0.0 && std::isfinite(tre_m(i)))) continue;
    const double ratio = tre_m(i) / sd_m(i);
    sum_sq += ratio * ratio;
    if (ratio <= 2.0) ++within;
    ++out.n;
  }
  if (out.n > 0) {
    out.rms_ratio = std::sqrt(sum_sq / static_cast<double>(out.n));
    out.within_2sigma = static_cast<double>(within) / static_cast<double>(out.n);
  }
  return out;
}

}  // namespace vrreg
