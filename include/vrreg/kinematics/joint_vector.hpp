#pragma once
// Joint vectors and angle arithmetic shared by every kinematics function. SI: radians.
#include <cmath>
#include <numbers>

#include <Eigen/Core>

namespace vrreg::kinematics {

/// Most joints a chain may have (fixed capacity keeps IK results free of heap allocations).
inline constexpr int kMaxJoints = 12;

/// A joint vector [rad], dynamic size up to kMaxJoints, stored inline.
using JointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxJoints, 1>;

/// Read-only view of any joint vector (JointVector, Eigen::VectorXd, a Map of std::vector) [rad].
using JointRef = Eigen::Ref<const Eigen::VectorXd>;

/// Wraps an angle [rad] to (-pi, pi].
inline double wrap_angle(double angle_rad) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double wrapped = std::remainder(angle_rad, kTwoPi);  // in [-pi, pi]
  if (wrapped <= -std::numbers::pi) wrapped += kTwoPi;
  return wrapped;
}

}  // namespace vrreg::kinematics
