// SPDX-License-Identifier: Apache-2.0
#pragma once
// Noise level from repeat readings and the rho criterion (paper section 4.3, Eq. 9).
#include <optional>
#include <vector>

#include "vrreg/core/measurement.hpp"

namespace vrreg {

/// sigma_opt: sqrt of the average, over locations with >= 2 readings, of the per-axis sample
/// variance of the repeat readings (averaged over x, y, z): a per-axis standard deviation [m].
/// Empty when no location has repeats.
std::optional<double> sigma_opt_m(const std::vector<Location>& locations);

/// The median number of readings averaged into a location (at least 1 each); 1 when empty. The
/// noise of one averaged reading is sigma_opt over its square root.
int median_readings(const std::vector<Location>& locations);

/// The orientation's sigma_opt: sqrt of the average, over locations with a measured orientation
/// and >= 2 readings, of the per-axis sample variance of the readings' angles about their mean
/// (Location::orientation_sq_dev_rad2 over 3 (n - 1)) [rad]. Empty when none has repeats.
std::optional<double> sigma_opt_rad(const std::vector<Location>& locations);

/// sigma_noise = sqrt(sigma_opt^2 + sigma_rep^2) (Eq. 9) [m].
double sigma_noise_m(double sigma_opt_m, double sigma_rep_m);

/// rho = sigma_L / sigma_noise: RRBC helps when rho > 2.5 (paper section 5.1).
double rho(double sigma_l_m, double sigma_noise_m);

/// The threshold on rho below which RRBC is not expected to help.
inline constexpr double kRhoThreshold = 2.5;

/// The noise figures of a fiducial set (section 4.3), each present when it can be computed.
struct NoiseFigures {
  std::optional<double> sigma_opt_m{};    ///< from repeat readings [m]
  std::optional<double> sigma_rep_m{};    ///< robot repeatability as given [m]
  std::optional<double> sigma_noise_m{};  ///< Eq. 9, when sigma_opt or sigma_rep is known [m]
  std::optional<double> rho{};            ///< sigma_L / sigma_noise, when sigma_noise > 0
  /// rho is an upper bound: sigma_rep was not given, so sigma_noise counts the sensor only.
  [[nodiscard]] bool rho_is_upper_bound() const { return rho && !sigma_rep_m; }
};

/// sigma_noise (Eq. 9) and rho from sigma_opt [m] (empty: unknown), sigma_rep [m] (empty: not
/// given) and sigma_L [m] (Eq. 1): the one place where these are combined.
NoiseFigures noise_figures(std::optional<double> sigma_opt_m, std::optional<double> sigma_rep_m,
                           double sigma_l_m);

}  // namespace vrreg
