// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/distributions.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <unsupported/Eigen/SpecialFunctions>

#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

// The x with survival(x) = tail for a decreasing survival function on [0, inf).
double upper_quantile(double tail, const std::function<double(double)>& survival) {
  VRREG_THROW_UNLESS(tail > 0.0 && tail < 1.0,
                     "quantile: the tail must be in (0, 1), got " << tail);
  double lo = 0.0;
  double hi = 1.0;
  while (survival(hi) > tail) {
    lo = hi;
    hi *= 2.0;
  }
  for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (survival(mid) > tail ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double chi_square_survival(double x, double k) {
  VRREG_THROW_UNLESS(k > 0.0 && std::isfinite(k) && std::isfinite(x) && x >= 0.0,
                     "chi-square: needs k > 0 and x >= 0, got k = " << k << ", x = " << x);
  return Eigen::numext::igammac(0.5 * k, 0.5 * x);
}

double chi_square_quantile_upper(double tail, double k) {
  return upper_quantile(tail, [k](double x) { return chi_square_survival(x, k); });
}

double f_survival(double x, double d1, double d2) {
  VRREG_THROW_UNLESS(d1 > 0.0 && d2 > 0.0 && std::isfinite(d1) && std::isfinite(d2) &&
                         std::isfinite(x) && x >= 0.0,
                     "F distribution: needs d1, d2 > 0 and x >= 0, got d1 = "
                         << d1 << ", d2 = " << d2 << ", x = " << x);
  // P(F > x) = I_{d2 / (d2 + d1 x)}(d2 / 2, d1 / 2).
  return Eigen::numext::betainc(0.5 * d2, 0.5 * d1, d2 / (d2 + d1 * x));
}

double f_quantile_upper(double tail, double d1, double d2) {
  return upper_quantile(tail, [d1, d2](double x) { return f_survival(x, d1, d2); });
}

double squared_sum_bound(double tail, double k, double variance_dof) {
  VRREG_THROW_UNLESS(variance_dof >= 0.0, "the variance's degrees of freedom must be >= 0");
  if (variance_dof == 0.0) return chi_square_quantile_upper(tail, k);
  return k * f_quantile_upper(tail, k, variance_dof);
}

double split_rate(double tail, double k1, double k2, double variance_dof) {
  VRREG_THROW_UNLESS(tail > 0.0 && tail < 1.0, "split rate: the tail must be in (0, 1)");
  VRREG_THROW_UNLESS(k1 > 0.0 && k2 > 0.0 && std::isfinite(variance_dof) && variance_dof >= 0.0,
                     "split rate: needs k1, k2 > 0 and a variance dof >= 0");
  const double independent = -std::expm1(0.5 * std::log1p(-tail));
  if (variance_dof == 0.0) return independent;
  // A cell checked again and again asks the same question: ~5 ms each, so remembered.
  static std::mutex mutex;
  static std::map<std::array<double, 4>, double> known;
  const std::array<double, 4> key{tail, k1, k2, variance_dof};
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = known.find(key); it != known.end()) return it->second;
  }
  const double nu = variance_dof;
  // Simpson's rule over u in chi2_nu's bulk (beyond 12 sd the density is below 1e-20).
  const double hi = nu + 12.0 * std::sqrt(2.0 * nu) + 40.0;
  constexpr int kIntervals = 800;
  const double h = hi / kIntervals;
  const auto both_pass = [&](double beta) {
    const double t1 = k1 * f_quantile_upper(beta, k1, nu);
    const double t2 = k2 * f_quantile_upper(beta, k2, nu);
    double sum = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
      const double u = i * h;
      const double density = u == 0.0 ? 0.0
                                      : std::exp((0.5 * nu - 1.0) * std::log(u) - 0.5 * u -
                                                 0.5 * nu * std::log(2.0) - std::lgamma(0.5 * nu));
      const double pass = (1.0 - chi_square_survival(t1 * u / nu, k1)) *
                          (1.0 - chi_square_survival(t2 * u / nu, k2));
      sum += (i == 0 || i == kIntervals ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0)) * density * pass;
    }
    return sum * h / 3.0;
  };
  // P(either alarms) rises with beta; the dependence makes beta at least the independent one.
  double lo = independent;
  double hi_beta = tail;
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi_beta);
    (1.0 - both_pass(mid) < tail ? lo : hi_beta) = mid;
  }
  const double beta = 0.5 * (lo + hi_beta);
  const std::lock_guard<std::mutex> lock(mutex);
  if (known.size() < 4096) known.emplace(key, beta);
  return beta;
}

}  // namespace vrreg
