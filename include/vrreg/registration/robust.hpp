// SPDX-License-Identifier: Apache-2.0
#pragma once
// Outlier-robust registration: finds fiducials that break the rigid-body condition grossly (a
// swapped or mislabelled marker) and registers without them. For point sets without a correction
// field: residuals against one rigid fit hold the robot's systematic error, so the front door's
// `--robust` judges fiducials against their neighbours' corrections instead
// (correction/outliers.hpp, docs/outliers.md).
//
// Method (documented threshold):
//  1. Seed: each point's score is the median over up to 64 reference points of |L_ij| (Eq. 1),
//     which needs no registration. Points scoring above 3 x median score (+ min_threshold_m) are
//     left out of the first fit.
//  2. Fit on the inliers (register_rigid); sigma = median inlier residual / 1.5382 (the median of
//     the norm of a 3D Gaussian with per-axis sigma 1). A point is an outlier when its residual
//     exceeds max(threshold_sigmas * sigma, min_threshold_m). Refit; repeat until the set is
//     stable.
#include <string>
#include <vector>

#include "vrreg/registration/rigid.hpp"

namespace vrreg {

/// Options for register_rigid_robust.
struct RobustRegistrationOptions {
  RegistrationOptions registration{};
  double threshold_sigmas = 5.0;      ///< P(|r| > 5 sigma) = 1.4e-5 for 3D Gaussian residuals
  double min_threshold_m = 1e-6;      ///< a point this close is never rejected
  double max_outlier_fraction = 0.5;  ///< beyond this the data are called unusable
  int max_iterations = 20;
  void validate() const;
};

/// Result of register_rigid_robust; `registration` is the fit on the inliers, with residuals of
/// ALL points (so rejected points show how far off they are).
struct RobustRegistrationResult {
  RegistrationResult registration{};
  std::vector<Eigen::Index> rejected{};  ///< column indices of the rejected points, ascending
  double sigma_m = 0.0;                  ///< robust per-axis residual scale
  double threshold_m = 0.0;              ///< the residual above which points were rejected
  int iterations = 0;
  bool converged = false;  ///< false: too many outliers or no stable set
  std::string message{};   ///< why not converged
};

/// Registers sensor onto robot points (Eq. 2) after rejecting gross outliers (see file comment).
RobustRegistrationResult register_rigid_robust(const ConstPoints3Ref& points_sensor_m,
                                               const ConstPoints3Ref& points_robot_m,
                                               const RobustRegistrationOptions& options = {});

}  // namespace vrreg
