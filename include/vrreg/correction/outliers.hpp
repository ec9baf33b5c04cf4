// SPDX-License-Identifier: Apache-2.0
#pragma once
// Finding the bad fiducial with RRBC in mind: each fiducial's correction (Eq. 6) is judged against
// what its neighbours predict for it — a leave-one-out (LOO) local affine fit of the correction
// field over its nearest fiducials of the same arm configuration — relative to the noise, not
// against one rigid fit (whose residuals hold the robot's systematic error).
//
// Method (docs/outliers.md):
//  1. Prediction: p_j = sum_k w_jk eps_k over the k nearest fiducials of the same group, w the
//     weights of a least-squares affine fit in the nominal robot positions, evaluated at Y_j. An
//     affine field is predicted exactly, so the deviation d_j = eps_j - p_j does not depend on
//     the registration {R, tau} at all (a change of it adds an affine field to eps).
//  2. Scale: with per-axis noise sigma on every eps, Var(d_j) = sigma^2 (1 + sum_k w_jk^2) per
//     axis and t_j = |d_j|^2 / (sigma^2 (1 + sum w^2)) is chi-square with 3 degrees of freedom.
//     sigma is the measured noise sigma_noise (Eq. 9) or, when the deviations spread wider than
//     that (interpolation error between neighbours), their robust spread
//     sqrt(median t'_j / 2.366); without a measured noise, the spread.
//  3. Bound: t_j > chi2_3 quantile at 1 - a', a' = 1 - (1 - a)^(1/J) (Sidak): a clean set of J
//     judged fiducials loses any with probability a (false_alarm_rate).
//  4. Iteration: the worst fiducial beyond the bound is rejected and its neighbours predicted
//     again without it (a gross outlier contaminates its neighbours' predictions), until none is.
//     Then any rejected fiducial within the bound against its inlier neighbours is re-admitted
//     (it was spoiled by a worse one), and the two steps repeat until nothing changes.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// Options of detect_outlier_fiducials.
struct OutlierOptions {
  double false_alarm_rate = 0.01;  ///< chance that a clean fiducial set loses any fiducial
  int neighbours = 26;             ///< nearest fiducials of the same group for the LOO fit
  double min_deviation_m = 1e-6;   ///< a deviation this small is never an outlier [m]
  double max_outlier_fraction = 0.25;  ///< beyond this the set is called unusable
  /// Throws InputError on a rate outside (0, 1), fewer than 6 neighbours, a negative deviation or
  /// a fraction outside (0, 1).
  void validate() const;
};

/// One rejected fiducial, judged against its inlier neighbours.
struct FiducialOutlier {
  Eigen::Index fiducial = 0;  ///< column in the fiducial set
  Eigen::Vector3d deviation_sensor_m = Eigen::Vector3d::Zero();  ///< eps_j - p_j, sensor frame [m]
  double sigmas = 0.0;  ///< |d_j| / (sigma sqrt(1 + sum w^2)): how far off, in standard deviations
  /// The fill: the inlier neighbours and weights that predict its correction (Eq. 7-like), empty
  /// when too few inliers surround it (then it cannot be filled, only dropped).
  std::vector<Eigen::Index> fill_fiducials{};
  std::vector<double> fill_weights{};
  [[nodiscard]] bool can_fill() const { return !fill_fiducials.empty(); }
  /// sum_k w_k eps_k over the fill stencil (eps: corrections of all fiducials, sensor frame [m]).
  [[nodiscard]] Eigen::Vector3d fill(const ConstPoints3Ref& corrections_sensor_m) const;
};

/// Result of detect_outlier_fiducials.
struct OutlierDetection {
  std::vector<FiducialOutlier> outliers{};  ///< in ascending column order
  double sigma_m = 0.0;                   ///< per-axis scale used (noise or spread) [m]
  std::optional<double> sigma_noise_m{};  ///< the measured noise given [m]
  double sigma_spread_m = 0.0;            ///< robust per-axis spread of the LOO deviations [m]
  bool scale_is_noise = false;            ///< sigma_m is sigma_noise (else the spread)
  double threshold_sigmas = 0.0;          ///< sqrt of the chi-square bound on t_j
  int n_judged = 0;  ///< fiducials with enough neighbours to be judged (the J of the bound)
  int iterations = 0;  ///< worst-first rejections made (re-admitted ones included)
  bool converged = false;  ///< false: more than max_outlier_fraction rejected
  std::string message{};   ///< why not converged
};

/// Judges every fiducial's correction eps_j (Eq. 6) against its neighbours' LOO prediction (see
/// the file comment). fiducials_robot_m: nominal robot positions [m]; corrections_sensor_m: eps
/// per fiducial [m]; groups: arm configuration per fiducial (neighbours only within a group;
/// empty: one group); sigma_noise_m: measured per-axis noise (Eq. 9) [m], if known. Throws
/// InputError on mismatched sizes or non-finite values.
OutlierDetection detect_outlier_fiducials(const ConstPoints3Ref& fiducials_robot_m,
                                          const ConstPoints3Ref& corrections_sensor_m,
                                          const std::vector<int>& groups,
                                          std::optional<double> sigma_noise_m,
                                          const OutlierOptions& options = {});

/// The chi-square bound of step 3: t with P(chi2_3 > t) = 1 - (1 - rate)^(1 / n_tests).
double chi_square3_family_bound(double false_alarm_rate, int n_tests);

}  // namespace vrreg
