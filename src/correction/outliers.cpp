// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/outliers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "loo_stencil.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

using detail::LooStencil;

// Rounds of rejection and re-admission (a bound on cycling; one round is the rule).
constexpr int kMaxRounds = 5;

// Median of the chi-square distribution with 3 degrees of freedom.
constexpr double kChiSquare3Median = 2.365973884375;

// P(chi2_3 > t) = erfc(sqrt(t/2)) + sqrt(2t/pi) exp(-t/2).
double chi_square3_survival(double t) {
  return std::erfc(std::sqrt(0.5 * t)) + std::sqrt(2.0 * t / std::numbers::pi) * std::exp(-0.5 * t);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2 == 1) return *mid;
  return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

// One fiducial's LOO state: its stencil and |d_j|^2 / (1 + sum w^2).
struct Judgement {
  LooStencil stencil;
  Eigen::Vector3d deviation_m = Eigen::Vector3d::Zero();
  double reduced_sq_m2 = 0.0;
};

Judgement judge(const ConstPoints3Ref& robot_m, const ConstPoints3Ref& eps_m, Eigen::Index j,
                const std::vector<Eigen::Index>& neighbours, const std::vector<bool>& inlier) {
  Judgement out;
  out.stencil = detail::loo_stencil(robot_m, j, neighbours, inlier);
  if (!out.stencil.ok) return out;
  Eigen::Vector3d prediction = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < out.stencil.fiducial.size(); ++i) {
    prediction += out.stencil.weight[i] * eps_m.col(out.stencil.fiducial[i]);
  }
  out.deviation_m = eps_m.col(j) - prediction;
  out.reduced_sq_m2 = out.deviation_m.squaredNorm() / out.stencil.variance_factor;
  return out;
}

}  // namespace

void OutlierOptions::validate() const {
  VRREG_THROW_UNLESS(false_alarm_rate > 0.0 && false_alarm_rate < 1.0,
                     "the false-alarm rate must be in (0, 1), got " << false_alarm_rate);
  VRREG_THROW_UNLESS(neighbours >= 6, "the LOO fit needs at least 6 neighbours, got " << neighbours);
  VRREG_THROW_UNLESS(min_deviation_m >= 0.0 && std::isfinite(min_deviation_m),
                     "min_deviation_m must be finite and >= 0, got " << min_deviation_m);
  VRREG_THROW_UNLESS(max_outlier_fraction > 0.0 && max_outlier_fraction < 1.0,
                     "max_outlier_fraction must be in (0, 1), got " << max_outlier_fraction);
}

Eigen::Vector3d FiducialOutlier::fill(const ConstPoints3Ref& corrections_sensor_m) const {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < fill_fiducials.size(); ++i) {
    sum += fill_weights[i] * corrections_sensor_m.col(fill_fiducials[i]);
  }
  return sum;
}

double chi_square3_family_bound(double false_alarm_rate, int n_tests) {
  VRREG_THROW_UNLESS(false_alarm_rate > 0.0 && false_alarm_rate < 1.0 && n_tests > 0,
                     "chi-square bound: rate " << false_alarm_rate << ", tests " << n_tests);
  // Sidak: per test a' = 1 - (1 - a)^(1/J), computed without cancellation.
  const double per_test = -std::expm1(std::log1p(-false_alarm_rate) / n_tests);
  double lo = 0.0;
  double hi = 1.0;
  while (chi_square3_survival(hi) > per_test) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (chi_square3_survival(mid) > per_test ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

OutlierDetection detect_outlier_fiducials(const ConstPoints3Ref& fiducials_robot_m,
                                          const ConstPoints3Ref& corrections_sensor_m,
                                          const std::vector<int>& groups,
                                          std::optional<double> sigma_noise_m,
                                          const OutlierOptions& options) {
  options.validate();
  const Eigen::Index n = fiducials_robot_m.cols();
  VRREG_THROW_UNLESS(corrections_sensor_m.cols() == n,
                     "outliers: " << corrections_sensor_m.cols() << " corrections for " << n
                                  << " fiducials");
  VRREG_THROW_UNLESS(groups.empty() || groups.size() == static_cast<std::size_t>(n),
                     "outliers: " << groups.size() << " group labels for " << n << " fiducials");
  VRREG_THROW_UNLESS(fiducials_robot_m.allFinite() && corrections_sensor_m.allFinite(),
                     "outliers: positions and corrections must be finite");
  VRREG_THROW_UNLESS(!sigma_noise_m || (std::isfinite(*sigma_noise_m) && *sigma_noise_m >= 0.0),
                     "outliers: the noise must be finite and >= 0, got " << *sigma_noise_m);

  OutlierDetection out;
  out.sigma_noise_m = sigma_noise_m;
  const auto neighbours = detail::group_neighbours(fiducials_robot_m, groups, options.neighbours);
  // Who has j among its neighbours: only they are judged again when j is rejected.
  std::vector<std::vector<Eigen::Index>> used_by(static_cast<std::size_t>(n));
  for (Eigen::Index j = 0; j < n; ++j) {
    for (const Eigen::Index k : neighbours[static_cast<std::size_t>(j)]) {
      used_by[static_cast<std::size_t>(k)].push_back(j);
    }
  }
  std::vector<bool> inlier(static_cast<std::size_t>(n), true);
  std::vector<Judgement> judged(static_cast<std::size_t>(n));
  for (Eigen::Index j = 0; j < n; ++j) {
    judged[static_cast<std::size_t>(j)] = judge(fiducials_robot_m, corrections_sensor_m, j,
                                                neighbours[static_cast<std::size_t>(j)], inlier);
  }
  // J of the bound: fiducials judged on the full set (fixed, so the bound does not drift).
  out.n_judged = static_cast<int>(std::count_if(judged.begin(), judged.end(),
                                                [](const Judgement& g) { return g.stencil.ok; }));
  if (out.n_judged == 0) {
    out.converged = true;
    return out;
  }
  const double bound = chi_square3_family_bound(options.false_alarm_rate, out.n_judged);
  out.threshold_sigmas = std::sqrt(bound);
  const auto max_outliers =
      static_cast<std::size_t>(options.max_outlier_fraction * static_cast<double>(n));
  std::vector<Eigen::Index> rejected;
  const auto rejudge_users = [&](Eigen::Index k) {
    for (const Eigen::Index j : used_by[static_cast<std::size_t>(k)]) {
      judged[static_cast<std::size_t>(j)] = judge(fiducials_robot_m, corrections_sensor_m, j,
                                                  neighbours[static_cast<std::size_t>(j)], inlier);
    }
  };
  const auto t_of = [&](const Judgement& g) {
    if (g.deviation_m.norm() <= options.min_deviation_m) return 0.0;
    return out.sigma_m > 0.0 ? g.reduced_sq_m2 / (out.sigma_m * out.sigma_m)
                             : std::numeric_limits<double>::infinity();
  };
  out.iterations = 0;
  for (int round = 0; round < kMaxRounds; ++round) {
    // Worst first: reject the worst inlier beyond the bound, judge its users again, repeat.
    for (;; ++out.iterations) {
      std::vector<double> reduced;
      for (Eigen::Index j = 0; j < n; ++j) {
        const Judgement& g = judged[static_cast<std::size_t>(j)];
        if (inlier[static_cast<std::size_t>(j)] && g.stencil.ok) reduced.push_back(g.reduced_sq_m2);
      }
      out.sigma_spread_m = std::sqrt(median(reduced) / kChiSquare3Median);
      out.scale_is_noise = sigma_noise_m && *sigma_noise_m >= out.sigma_spread_m;
      out.sigma_m = out.scale_is_noise ? *sigma_noise_m : out.sigma_spread_m;
      Eigen::Index worst = -1;
      double worst_t = bound;
      for (Eigen::Index j = 0; j < n; ++j) {
        const Judgement& g = judged[static_cast<std::size_t>(j)];
        if (!inlier[static_cast<std::size_t>(j)] || !g.stencil.ok) continue;
        const double t = t_of(g);
        if (t > worst_t) {
          worst_t = t;
          worst = j;
        }
      }
      if (worst < 0) break;
      if (rejected.size() + 1 > max_outliers) {
        out.message = "more than " +
                      std::to_string(static_cast<int>(100 * options.max_outlier_fraction)) +
                      "% of the fiducials disagree with their neighbours: no consistent "
                      "correction field";
        return out;
      }
      inlier[static_cast<std::size_t>(worst)] = false;
      rejected.push_back(worst);
      rejudge_users(worst);
    }
    // Re-admission: a fiducial rejected while a worse neighbour still spoiled its prediction may
    // agree with its clean neighbours after all.
    bool readmitted = false;
    for (auto it = rejected.begin(); it != rejected.end();) {
      Judgement g = judge(fiducials_robot_m, corrections_sensor_m, *it,
                          neighbours[static_cast<std::size_t>(*it)], inlier);
      if (g.stencil.ok && t_of(g) <= bound) {
        inlier[static_cast<std::size_t>(*it)] = true;
        judged[static_cast<std::size_t>(*it)] = std::move(g);
        rejudge_users(*it);
        it = rejected.erase(it);
        readmitted = true;
      } else {
        ++it;
      }
    }
    if (!readmitted) break;
  }
  out.converged = true;
  std::sort(rejected.begin(), rejected.end());
  for (const Eigen::Index j : rejected) {
    // Judged against its inlier neighbours only: the deviation a user should look at.
    const Judgement g = judge(fiducials_robot_m, corrections_sensor_m, j,
                              neighbours[static_cast<std::size_t>(j)], inlier);
    FiducialOutlier o;
    o.fiducial = j;
    const Judgement& first = g.stencil.ok ? g : judged[static_cast<std::size_t>(j)];
    o.deviation_sensor_m = first.deviation_m;
    o.sigmas = out.sigma_m > 0.0 ? std::sqrt(first.reduced_sq_m2) / out.sigma_m
                                 : std::numeric_limits<double>::infinity();
    if (g.stencil.ok) {
      o.fill_fiducials = g.stencil.fiducial;
      o.fill_weights = g.stencil.weight;
    }
    out.outliers.push_back(std::move(o));
  }
  return out;
}

}  // namespace vrreg
