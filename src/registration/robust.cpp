// SPDX-License-Identifier: Apache-2.0
#include "vrreg/registration/robust.hpp"

#include <algorithm>
#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

// Median of the norm of a 3D standard Gaussian vector (Maxwell distribution).
constexpr double kMaxwellMedian = 1.5381722; 
constexpr Eigen::Index kReferencePoints = 64;

double median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2 == 1) return *mid;
  return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

// Rigid-body seed: per point, the median |L_ij| against evenly spaced reference points.
std::vector<bool> seed_inliers(const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                               double min_threshold_m) {
  const Eigen::Index n = x.cols();
  const Eigen::Index n_ref = std::min(n, kReferencePoints);
  std::vector<double> score(static_cast<std::size_t>(n));
  std::vector<double> l_abs;
  for (Eigen::Index j = 0; j < n; ++j) {
    l_abs.clear();
    for (Eigen::Index k = 0; k < n_ref; ++k) {
      const Eigen::Index i = k * n / n_ref;
      if (i == j) continue;
      l_abs.push_back(std::abs((x.col(i) - x.col(j)).norm() - (y.col(i) - y.col(j)).norm()));
    }
    score[static_cast<std::size_t>(j)] = median(l_abs);
  }
  const double cut = 3.0 * median(score) + min_threshold_m;
  std::vector<bool> inlier(static_cast<std::size_t>(n));
  for (std::size_t j = 0; j < score.size(); ++j) inlier[j] = score[j] <= cut;
  return inlier;
}

Points3 take(const ConstPoints3Ref& p, const std::vector<bool>& keep) {
  Points3 out(3, std::count(keep.begin(), keep.end(), true));
  Eigen::Index k = 0;
  for (Eigen::Index j = 0; j < p.cols(); ++j) {
    if (keep[static_cast<std::size_t>(j)]) out.col(k++) = p.col(j);
  }
  return out;
}

}  // namespace

void RobustRegistrationOptions::validate() const {
  registration.validate();
  VRREG_THROW_UNLESS(threshold_sigmas > 0.0 && std::isfinite(threshold_sigmas),
                     "threshold_sigmas must be positive, got " << threshold_sigmas);
  VRREG_THROW_UNLESS(min_threshold_m >= 0.0 && std::isfinite(min_threshold_m),
                     "min_threshold_m must be non-negative, got " << min_threshold_m);
  VRREG_THROW_UNLESS(max_outlier_fraction > 0.0 && max_outlier_fraction < 1.0,
                     "max_outlier_fraction must be in (0, 1), got " << max_outlier_fraction);
  VRREG_THROW_UNLESS(max_iterations > 0, "max_iterations must be positive");
}

RobustRegistrationResult register_rigid_robust(const ConstPoints3Ref& points_sensor_m,
                                               const ConstPoints3Ref& points_robot_m,
                                               const RobustRegistrationOptions& options) {
  options.validate();
  // Full-set call validates sizes, finiteness and geometry with the usual messages.
  RobustRegistrationResult out;
  out.registration = register_rigid(points_sensor_m, points_robot_m, options.registration);
  const Eigen::Index n = points_sensor_m.cols();
  const auto max_outliers =
      static_cast<std::ptrdiff_t>(options.max_outlier_fraction * static_cast<double>(n));

  std::vector<bool> inlier = seed_inliers(points_sensor_m, points_robot_m, options.min_threshold_m);
  for (out.iterations = 1; out.iterations <= options.max_iterations; ++out.iterations) {
    const auto n_out = std::count(inlier.begin(), inlier.end(), false);
    if (n - n_out < 3 || n_out > max_outliers) {
      out.message = "more than " + std::to_string(static_cast<int>(100 * options.max_outlier_fraction)) +
                    "% of the fiducials look like outliers: no consistent rigid registration";
      return out;
    }
    const RegistrationResult fit = register_rigid(take(points_sensor_m, inlier),
                                                  take(points_robot_m, inlier),
                                                  options.registration);
    const SimilarityTransform& t = fit.T_robot_sensor;
    Eigen::VectorXd residuals(n);
    std::vector<double> inlier_residuals;
    for (Eigen::Index j = 0; j < n; ++j) {
      residuals[j] = (t.apply(points_sensor_m.col(j)) - points_robot_m.col(j)).norm();
      if (inlier[static_cast<std::size_t>(j)]) inlier_residuals.push_back(residuals[j]);
    }
    out.sigma_m = median(inlier_residuals) / kMaxwellMedian;
    out.threshold_m = std::max(options.threshold_sigmas * out.sigma_m, options.min_threshold_m);
    std::vector<bool> next(static_cast<std::size_t>(n));
    for (Eigen::Index j = 0; j < n; ++j) next[static_cast<std::size_t>(j)] = residuals[j] <= out.threshold_m;

    out.registration = fit;
    out.registration.residuals_m = residuals;
    if (next == inlier) {
      out.converged = true;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (!inlier[static_cast<std::size_t>(j)]) out.rejected.push_back(j);
      }
      return out;
    }
    inlier = std::move(next);
  }
  out.iterations = options.max_iterations;
  out.message = "the inlier set did not settle in " + std::to_string(options.max_iterations) +
                " iterations";
  return out;
}

}  // namespace vrreg
