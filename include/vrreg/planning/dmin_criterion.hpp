// SPDX-License-Identifier: Apache-2.0
#pragma once
// The lower limit on the target-fiducial distance (paper section 6, Eq. 9): RRBC helps only when
// rho > 2.5, so the nearest fiducials must be farther than 2.5 sigma_noise from the target.
namespace vrreg::planning {

/// sigma_noise of the paper's UR5 test bed, dataset A1 (Table 1): 0.114 mm, in m.
inline constexpr double kPaperSigmaNoiseM = 0.114e-3;

/// sigma_noise of the paper's KUKA LWR 4+ test bed (section 5.2): 0.077 mm, in m.
inline constexpr double kPaperKukaSigmaNoiseM = 0.077e-3;

/// Factor of Eq. 9: d_min > 2.5 sigma_noise.
inline constexpr double kDminNoiseFactor = 2.5;

/// Outcome of the Eq. 9 check.
struct DminCheck {
  double d_min_m = 0.0;        ///< nearest target-fiducial distance [m]
  double sigma_noise_m = 0.0;  ///< noise level used [m]
  double threshold_m = 0.0;    ///< 2.5 * sigma_noise [m]
  bool ok = false;             ///< d_min > threshold
  bool forced = false;         ///< failed but the caller chose to go on
};

/// Checks d_min > 2.5 sigma_noise (Eq. 9). Throws InputError (with both values and the smallest
/// spacing that passes) when it fails and `force` is false; both must be finite and positive.
DminCheck check_dmin(double d_min_m, double sigma_noise_m, bool force);

/// Smallest grid spacing A [m] whose d_min = sqrt(3)/2 * A passes Eq. 9 for `sigma_noise_m`.
double min_spacing_for_noise_m(double sigma_noise_m);

}  // namespace vrreg::planning
