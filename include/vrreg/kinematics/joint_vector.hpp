// SPDX-License-Identifier: Apache-2.0
#pragma once
// Joint vectors and angle arithmetic shared by every kinematics function. SI: radians.
#include <Eigen/Core>
#include <cmath>
#include <numbers>

namespace vrreg::kinematics {

/// Most joints a chain may have (fixed capacity keeps IK results free of heap allocations).
inline constexpr int kMaxJoints = 12;

/// A joint vector [rad], dynamic size up to kMaxJoints, stored inline.
using JointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxJoints, 1>;

/// Read-only view of any joint vector (JointVector, Eigen::VectorXd, a Map of std::vector) [rad].
using JointRef = Eigen::Ref<const Eigen::VectorXd>;

/// Wraps an angle [rad] to (-pi, pi].
inline double wrap_angle(double angle_rad) {
  constexpr double kPi = std::numbers::pi;
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  // Fast path for the usual case (sums and differences of a few angles in (-pi, pi]).
  if (angle_rad > -kPi && angle_rad <= kPi) return angle_rad;
  if (angle_rad > kPi && angle_rad <= 3.0 * kPi) {
    const double w = angle_rad - kTwoPi;
    if (w > -kPi) return w;
  } else if (angle_rad <= -kPi && angle_rad > -3.0 * kPi) {
    const double w = angle_rad + kTwoPi;
    if (w <= kPi && w > -kPi) return w;
  }
  double wrapped = std::remainder(angle_rad, kTwoPi);  // in [-pi, pi]
  if (wrapped <= -kPi) wrapped += kTwoPi;
  return wrapped;
}

}  // namespace vrreg::kinematics
