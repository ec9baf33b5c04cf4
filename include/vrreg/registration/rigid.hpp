// SPDX-License-Identifier: Apache-2.0
#pragma once
// Point-based rigid registration (paper Eq. 2): least squares via the SVD of the 3x3
// cross-covariance, always a proper rotation, optional uniform scale.
#include <Eigen/Core>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// Options for register_rigid.
struct RegistrationOptions {
  bool estimate_scale = false;  ///< also fit a uniform scale (Umeyama); off in the paper
  /// Smallest allowed ratio of the 2nd to the 1st singular value of the centred sensor points:
  /// below it the points are called collinear (or coincident) and registration refuses.
  double collinearity_tolerance = 1e-6;
  /// true: per-point residuals and FRE from them (a second pass). false: no residuals (empty
  /// residuals_m); FRE in closed form from the same one-pass moments as the transform,
  /// sum |b - b_mean|^2 + s^2 sum |a - a_mean|^2 - 2 s tr(R H) (weighted as Eq. 2), with a
  /// residual pass only for near-perfect fits (FRE below ~1e-3 of the spread); under 64 points
  /// the residuals path's numbers, without storing the residuals. 5x (10^3 points) to 25x (10^6)
  /// faster than Eigen::umeyama (docs/benchmarks.md); the transform agrees with the residuals
  /// path to ~1e-15, FRE to ~1e-16 (spread / FRE)^2 relative (2e-12 for 0.5 mm noise on a 0.3 m
  /// layout).
  bool residuals = true;
  void validate() const;
};

/// Result of register_rigid.
struct RegistrationResult {
  /// Maps sensor points onto robot points: Y ~ R X + tau (a similarity only with estimate_scale;
  /// T_robot_sensor.rigid() is the rigid transform otherwise).
  SimilarityTransform T_robot_sensor{};
  double fre_m = 0.0;             ///< FRE, Eq. 2 (weighted RMS when weights are given)
  Eigen::VectorXd residuals_m{};  ///< ||R X_j + tau - Y_j|| per point (if options.residuals)
  /// RMS spread of the fiducials along the principal axes, largest first [m]: sqrt of the singular
  /// values of the centred cross-covariance / J (exactly the point set's spread for rigid data).
  /// A small third value means a nearly planar layout, a small second one a nearly collinear one.
  Eigen::Vector3d spread_m = Eigen::Vector3d::Zero();
  double collinearity = 0.0;  ///< spread_m(1) / spread_m(0): 0 for collinear points
};

/// Registers sensor points onto robot points (Eq. 2): minimises sum_j w_j ||s R X_j + tau -
/// Y_j||^2. points_sensor_m, points_robot_m: corresponding points [m]; weights: one non-negative
/// value per point, or empty for equal weights. Throws InputError for fewer than 3 points,
/// non-finite values, mismatched sizes or collinear / coincident points.
RegistrationResult register_rigid(
    const ConstPoints3Ref& points_sensor_m, const ConstPoints3Ref& points_robot_m,
    const RegistrationOptions& options = {},
    const Eigen::Ref<const Eigen::VectorXd>& weights = Eigen::VectorXd());

}  // namespace vrreg
