// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/dmin_criterion.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::planning {

double min_spacing_for_noise_m(double sigma_noise_m) {
  return kDminNoiseFactor * sigma_noise_m * 2.0 / std::sqrt(3.0);
}

DminCheck check_dmin(double d_min_m, double sigma_noise_m, bool force) {
  VRREG_THROW_UNLESS(std::isfinite(d_min_m) && d_min_m > 0.0,
                     "d_min check: d_min must be finite and positive, got " << d_min_m << " m");
  VRREG_THROW_UNLESS(
      std::isfinite(sigma_noise_m) && sigma_noise_m > 0.0,
      "d_min check: sigma_noise must be finite and positive, got " << sigma_noise_m << " m");
  DminCheck check;
  check.d_min_m = d_min_m;
  check.sigma_noise_m = sigma_noise_m;
  check.threshold_m = kDminNoiseFactor * sigma_noise_m;
  check.ok = d_min_m > check.threshold_m;
  check.forced = !check.ok && force;
  VRREG_THROW_UNLESS(
      check.ok || force,
      "d_min = " << format_mm(d_min_m)
                 << " mm is not above 2.5 * sigma_noise = " << format_mm(check.threshold_m)
                 << " mm (sigma_noise = " << format_mm(sigma_noise_m)
                 << " mm; paper Eq. 9): fiducials this close to the target see mostly noise and "
                    "RRBC is not expected to help; use a grid spacing above "
                 << format_mm(min_spacing_for_noise_m(sigma_noise_m)) << " mm, or force the plan");
  return check;
}

}  // namespace vrreg::planning
