// SPDX-License-Identifier: Apache-2.0
// Is today noisier than the registration? One visit's variance today against then.
#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/metrics/distributions.hpp"
#include "vrreg/metrics/monitor_check.hpp"

namespace vrreg {

VisitNoiseComparison compare_visit_noise(double variance_then_m2, double dof_then,
                                         double variance_today_m2, double dof_today, double rate) {
  VRREG_THROW_UNLESS(std::isfinite(variance_then_m2) && variance_then_m2 > 0.0 &&
                         std::isfinite(variance_today_m2) && variance_today_m2 > 0.0,
                     "visit noise: the variances must be > 0, got " << variance_then_m2 << " and "
                                                                    << variance_today_m2);
  VRREG_THROW_UNLESS(
      std::isfinite(dof_then) && dof_then >= 0.0 && std::isfinite(dof_today) && dof_today >= 0.0,
      "visit noise: degrees of freedom must be >= 0");
  VRREG_THROW_UNLESS(rate > 0.0 && rate < 1.0, "visit noise: the rate must be in (0, 1)");
  VisitNoiseComparison out;
  out.variance_then_m2 = variance_then_m2;
  out.dof_then = dof_then;
  out.variance_today_m2 = variance_today_m2;
  out.dof_today = dof_today;
  out.ratio = variance_today_m2 / variance_then_m2;
  if (dof_today == 0.0) return out;
  out.tested = true;
  // Known variance then: dof_today s^2 / sigma^2 ~ chi2; both estimated: s1^2 / s2^2 ~ F.
  out.p_value = dof_then == 0.0 ? chi_square_survival(dof_today * out.ratio, dof_today)
                                : f_survival(out.ratio, dof_today, dof_then);
  out.noisier = out.p_value < rate;
  return out;
}

}  // namespace vrreg
