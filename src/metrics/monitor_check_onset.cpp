// SPDX-License-Identifier: Apache-2.0
// Did a change come at once or grow? The checks since the registration, each a mean of the
// monitor points, fitted as mu + phi_c Delta: a step (every earlier phi 0 or 1) against a linear
// ramp in time, by their likelihood ratio.
#include <algorithm>
#include <cmath>
#include <limits>

#include "vrreg/core/check.hpp"
#include "vrreg/metrics/distributions.hpp"
#include "vrreg/metrics/monitor_check.hpp"

namespace vrreg {
namespace {

// The readings as rows of coordinates: y(c, 3 i + a), weight w(c, 3 i + a) (0: not read).
struct Stack {
  Eigen::MatrixXd y;
  Eigen::MatrixXd w;
};

// Weighted squares a fit with fractions `phi` (one per check) leaves, with mu and Delta fitted per
// coordinate; `mu`, `delta` receive them.
double fit_given_fractions(const Stack& s, const Eigen::VectorXd& phi, Eigen::VectorXd& mu,
                           Eigen::VectorXd& delta) {
  const Eigen::Index coords = s.y.cols();
  mu.resize(coords);
  delta.resize(coords);
  double rss = 0.0;
  for (Eigen::Index j = 0; j < coords; ++j) {
    const Eigen::VectorXd& w = s.w.col(j);
    const double s0 = w.sum(), s1 = w.dot(phi), s2 = w.dot(phi.cwiseAbs2());
    const double b0 = w.dot(s.y.col(j)), b1 = w.cwiseProduct(phi).dot(s.y.col(j));
    const double det = s0 * s2 - s1 * s1;  // > 0: the registration (phi 0) and today (1) weigh
    mu(j) = (s2 * b0 - s1 * b1) / det;
    delta(j) = (s0 * b1 - s1 * b0) / det;
    const Eigen::VectorXd r = s.y.col(j) - (mu(j) + delta(j) * phi.array()).matrix();
    rss += w.dot(r.cwiseAbs2());
  }
  return rss;
}

// Free fractions from `phi` (a step): alternate the earlier checks' fractions and (mu, Delta),
// each a least-squares solution, so the weighted squares only fall. `fractions` gets the
// earlier checks' own; returns the weighted squares they leave.
double free_fractions(const Stack& s, Eigen::VectorXd phi, std::vector<double>& fractions) {
  const Eigen::Index k = phi.size() - 2;
  Eigen::VectorXd mu, delta;
  double rss = fit_given_fractions(s, phi, mu, delta);
  for (int iteration = 0; iteration < 2000; ++iteration) {
    for (Eigen::Index c = 1; c <= k; ++c) {
      const Eigen::VectorXd w = s.w.row(c).transpose();
      const double den = w.dot(delta.cwiseAbs2());
      if (den > 0.0) phi(c) = w.cwiseProduct(delta).dot(s.y.row(c).transpose() - mu) / den;
    }
    const double next = fit_given_fractions(s, phi, mu, delta);
    const bool settled = rss - next <= 1e-12 * std::max(rss, 1.0);
    rss = next;
    if (settled) break;
  }
  fractions.assign(phi.data() + 1, phi.data() + 1 + k);
  return rss;
}

// The best linear ramp phi = clamp((t - start) / (end - start), 0, 1), start < end <= today,
// over a grid of starts and ends: the checks' times, the midpoints between them, and one interval
// before the first (a ramp already under way at it). The registration keeps phi 0.
double best_linear_ramp(const Stack& s, const Eigen::VectorXd& t) {
  const Eigen::Index rows = t.size();
  const double today = t(rows - 1);
  std::vector<double> grid{t(1) - (today - t(1))};
  for (Eigen::Index c = 1; c < rows; ++c) {
    grid.push_back(0.5 * (grid.back() + t(c)));
    grid.push_back(t(c));
  }
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  Eigen::VectorXd mu, delta, phi(rows);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < grid.size(); ++a) {
    for (std::size_t b = a + 1; b < grid.size(); ++b) {
      phi(0) = 0.0;
      for (Eigen::Index c = 1; c < rows; ++c)
        phi(c) = std::clamp((t(c) - grid[a]) / (grid[b] - grid[a]), 0.0, 1.0);
      if (phi(rows - 1) < 1.0) continue;  // today is the reference: 1
      best = std::min(best, fit_given_fractions(s, phi, mu, delta));
    }
  }
  return best;
}

}  // namespace

const char* to_string(ChangeOnset onset) {
  switch (onset) {
    case ChangeOnset::kUnknown:
      return "unknown";
    case ChangeOnset::kStep:
      return "step";
    case ChangeOnset::kRamp:
      return "ramp";
  }
  return "unknown";
}

ChangeOnsetTest classify_change_onset(const Eigen::Ref<const Eigen::VectorXd>& baseline_mean_sd_m,
                                      const std::vector<MonitorReadings>& earlier,
                                      const MonitorReadings& today, double rate) {
  VRREG_THROW_UNLESS(rate > 0.0 && rate < 1.0, "change onset: the rate must be in (0, 1)");
  const Eigen::Index n = today.difference_m.cols();
  const auto check_readings = [n](const MonitorReadings& r, bool all_read) {
    VRREG_THROW_UNLESS(r.difference_m.cols() == n && r.mean_sd_m.size() == n,
                       "change onset: a check has " << r.difference_m.cols() << " points and "
                                                    << r.mean_sd_m.size() << " sd, expected " << n);
    VRREG_THROW_UNLESS(r.difference_m.allFinite() && r.mean_sd_m.allFinite() &&
                           (r.mean_sd_m.array() >= 0.0).all() && std::isfinite(r.time_s),
                       "change onset: a reading, sd or time is not finite, or a sd is negative");
    VRREG_THROW_UNLESS(!all_read || (r.mean_sd_m.array() > 0.0).all(),
                       "change onset: today's sd must be > 0 for every point");
  };
  VRREG_THROW_UNLESS(n >= 1, "change onset: no monitor points");
  check_readings(today, true);
  VRREG_THROW_UNLESS(
      baseline_mean_sd_m.size() == n && baseline_mean_sd_m.allFinite() &&
          (baseline_mean_sd_m.array() > 0.0).all(),
      "change onset: the registration's sd must be > 0 for each of the " << n << " points");
  for (std::size_t c = 0; c < earlier.size(); ++c) {
    check_readings(earlier[c], false);
    VRREG_THROW_UNLESS(
        earlier[c].time_s < today.time_s && (c == 0 || earlier[c - 1].time_s <= earlier[c].time_s),
        "change onset: the earlier checks must be in time order, before today");
  }
  // The most recent earlier checks that read any of today's points.
  std::vector<const MonitorReadings*> used;
  for (auto it = earlier.rbegin(); it != earlier.rend(); ++it) {
    if ((it->mean_sd_m.array() > 0.0).any() && static_cast<int>(used.size()) < kMaxEarlierChecks)
      used.push_back(&*it);
  }
  std::reverse(used.begin(), used.end());
  ChangeOnsetTest out;
  const int k = static_cast<int>(used.size());
  out.earlier_checks = k;
  if (k == 0) {
    out.message =
        "no earlier check of these monitor points since the registration: a step "
        "cannot be told from a ramp";
    return out;
  }
  // Rows: the registration (its mean is the origin: 0), the earlier checks, today.
  Stack s;
  s.y = Eigen::MatrixXd::Zero(k + 2, 3 * n);
  s.w = Eigen::MatrixXd::Zero(k + 2, 3 * n);
  Eigen::VectorXd t(k + 2);
  const auto put = [&](Eigen::Index row, const MonitorReadings* r, const Eigen::VectorXd& sd) {
    for (Eigen::Index i = 0; i < n; ++i) {
      if (sd(i) <= 0.0) continue;
      for (int a = 0; a < 3; ++a) {
        s.y(row, 3 * i + a) = r ? r->difference_m(a, i) : 0.0;
        s.w(row, 3 * i + a) = 1.0 / (sd(i) * sd(i));
      }
    }
    t(row) = r ? r->time_s : 0.0;
  };
  put(0, nullptr, baseline_mean_sd_m);
  for (int c = 0; c < k; ++c)
    put(c + 1, used[static_cast<std::size_t>(c)], used[static_cast<std::size_t>(c)]->mean_sd_m);
  put(k + 1, &today, today.mean_sd_m);

  // Best step: the first `j` earlier checks unchanged, the rest at today's values, from a check
  // that found the change (a step is seen whole at once).
  Eigen::VectorXd mu, delta;
  Eigen::VectorXd best_phi;
  double best = std::numeric_limits<double>::infinity();
  for (int j = 0; j <= k; ++j) {
    if (j < k && !used[static_cast<std::size_t>(j)]->changed) continue;
    Eigen::VectorXd phi = Eigen::VectorXd::Zero(k + 2);
    phi.tail(k + 1 - j).setOnes();
    const double rss = fit_given_fractions(s, phi, mu, delta);
    if (rss < best) {
      best = rss;
      best_phi = phi;
      out.step_after = j - 1;
    }
  }
  out.step_chi2 = best;
  out.ramp_chi2 = std::min(best, best_linear_ramp(s, t));
  out.statistic = out.step_chi2 - out.ramp_chi2;
  out.bound = chi_square_quantile_upper(rate, 1.0);
  free_fractions(s, best_phi, out.fractions);
  const bool ramp = out.statistic > out.bound;
  out.onset = ramp ? ChangeOnset::kRamp : ChangeOnset::kStep;
  out.message = ramp ? "grew over the earlier checks" : "came at once";
  return out;
}

}  // namespace vrreg
