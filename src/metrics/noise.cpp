// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/noise.hpp"

#include <algorithm>
#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg {

std::optional<double> sigma_opt_m(const std::vector<Location>& locations) {
  double sum_var = 0.0;
  int used = 0;
  for (const Location& loc : locations) {
    if (loc.n_readings < 2) continue;
    sum_var += loc.sensor_sq_dev_m2.sum() / (3.0 * (loc.n_readings - 1));
    ++used;
  }
  if (used == 0) return std::nullopt;
  return std::sqrt(sum_var / used);
}

int median_readings(const std::vector<Location>& locations) {
  if (locations.empty()) return 1;
  std::vector<int> readings;
  for (const Location& l : locations) readings.push_back(std::max(l.n_readings, 1));
  std::nth_element(readings.begin(), readings.begin() + readings.size() / 2, readings.end());
  return readings[readings.size() / 2];
}

std::optional<double> sigma_opt_rad(const std::vector<Location>& locations) {
  double sum_var = 0.0;
  int used = 0;
  for (const Location& loc : locations) {
    if (loc.n_readings < 2 || !loc.q_sensor_marker) continue;
    sum_var += loc.orientation_sq_dev_rad2 / (3.0 * (loc.n_readings - 1));
    ++used;
  }
  if (used == 0) return std::nullopt;
  return std::sqrt(sum_var / used);
}

double sigma_noise_m(double sigma_opt, double sigma_rep) {
  VRREG_THROW_UNLESS(sigma_opt >= 0.0 && sigma_rep >= 0.0 && std::isfinite(sigma_opt) &&
                         std::isfinite(sigma_rep),
                     "noise levels must be finite and non-negative, got sigma_opt="
                         << sigma_opt << " m, sigma_rep=" << sigma_rep << " m");
  return std::hypot(sigma_opt, sigma_rep);
}

double rho(double sigma_l, double sigma_noise) {
  VRREG_THROW_UNLESS(sigma_noise > 0.0, "rho needs a positive sigma_noise, got " << sigma_noise);
  return sigma_l / sigma_noise;
}

NoiseFigures noise_figures(std::optional<double> sigma_opt, std::optional<double> sigma_rep,
                           double sigma_l) {
  NoiseFigures f;
  f.sigma_opt_m = sigma_opt;
  f.sigma_rep_m = sigma_rep;
  if (sigma_opt || sigma_rep) f.sigma_noise_m = sigma_noise_m(sigma_opt.value_or(0.0), sigma_rep.value_or(0.0));
  if (f.sigma_noise_m && *f.sigma_noise_m > 0.0) f.rho = rho(sigma_l, *f.sigma_noise_m);
  return f;
}

}  // namespace vrreg
