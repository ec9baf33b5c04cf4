// SPDX-License-Identifier: Apache-2.0
#pragma once
// Registration with an unknown marker offset (robot-sensor hand-eye calibration): from flange
// poses and the marker positions the sensor measured there, T_robot_sensor = {R, tau} and the
// marker's position p in the flange frame together. Model, per pose j (extends paper Eq. 2):
//   R y_j + tau = R_flange_j p + t_flange_j
// A closed-form linear start (the model is linear in R, tau, p before R is projected onto SO(3)),
// then Levenberg-Marquardt on (rotation, tau, p).
// When the sensor also gives the marker's orientation R_sensor_marker_j (a rigid-body tracker),
// rotation residuals are added: R R_sensor_marker_j = R_flange_j R_flange_marker, with the
// marker's orientation on the flange R_flange_marker a further unknown (3 parameters); position
// and rotation residuals are weighted by their noise, estimated from the residuals (variance
// components) unless the orientation noise is given.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// Options of estimate_marker_offset.
struct MarkerOffsetOptions {
  /// Smallest orientation spread (see MarkerOffsetResult::orientation_spread) for which the offset
  /// is called observable; below it the estimator refuses. 0.02 ~ a 1.1 degree tilt.
  double min_orientation_spread = 0.02;
  int max_iterations = 100;         ///< Levenberg-Marquardt iterations
  double step_tolerance_m = 1e-15;  ///< stop when the parameter step is below this [m, rad x m]
  /// Standard uncertainty of the robot's joint zero offsets [rad], for register_with_marker_offset
  /// (pipeline): propagated into p's uncertainty (systematic flange errors look like another
  /// offset). 0: the stated uncertainty covers noise only.
  double joint_offset_sigma_rad = 0.0;
  /// Standard deviation of the sensor's marker orientation, per axis [rad], when orientations
  /// are given. 0: estimated from the rotation residuals (with the position noise).
  double orientation_sigma_rad = 0.0;
  void validate() const;
};

/// Outcome of the estimation.
enum class MarkerOffsetStatus {
  kOk,            ///< estimated
  kUnobservable,  ///< the flange orientations do not vary enough: p is not determined
  kNotConverged,  ///< the refinement did not converge (values are the last iterate)
};

/// Lower-case name of a status ("ok", "unobservable", "not-converged").
const char* to_string(MarkerOffsetStatus status);

/// What estimate_marker_offset found.
struct MarkerOffsetResult {
  MarkerOffsetStatus status = MarkerOffsetStatus::kOk;
  std::string message{};            ///< why, when not kOk
  RigidTransform T_robot_sensor{};  ///< Y ~ R X + tau (Eq. 2), sensor -> robot
  Eigen::Vector3d p_flange_marker_m = Eigen::Vector3d::Zero();  ///< marker in the flange frame
  /// Standard uncertainties, per axis, from the Jacobian and the residual variance (s^2 (J'J)^-1).
  Eigen::Vector3d p_std_m = Eigen::Vector3d::Zero();            ///< of p, flange axes [m]
  Eigen::Vector3d translation_std_m = Eigen::Vector3d::Zero();  ///< of tau, robot axes [m]
  Eigen::Vector3d rotation_std_rad = Eigen::Vector3d::Zero();   ///< of R (small angles, robot axes)
  /// Covariance of (rotation increment [rad], tau [m], p [m]), 9 x 9.
  Eigen::Matrix<double, 9, 9> covariance = Eigen::Matrix<double, 9, 9>::Zero();
  double fre_m = 0.0;             ///< RMS residual distance (FRE, Eq. 2 with the offset)
  double sigma_m = 0.0;           ///< residual standard deviation per coordinate, dof-corrected
  Eigen::VectorXd residuals_m{};  ///< ||R y_j + tau - T_robot_flange_j p|| per pose
  /// sqrt of the smallest eigenvalue of I - M'M, M the mean flange rotation: ~ the RMS tilt [rad]
  /// about the worst axis. 0 when every pose has one orientation (p cannot be told from tau).
  double orientation_spread = 0.0;
  /// Condition number of the Jacobian with unit-norm columns at the solution (1 is ideal).
  double condition_number = 0.0;
  int iterations = 0;  ///< Levenberg-Marquardt iterations taken
  /// Set when marker orientations were given: the marker's orientation in the flange frame and
  /// its standard uncertainty (small angles, flange axes), the orientation noise used
  /// (estimated or given), and the rotation residual angle per pose. The covariance above is
  /// then the marginal one of (rotation, tau, p).
  bool has_marker_orientation = false;
  Eigen::Quaterniond q_flange_marker = Eigen::Quaterniond::Identity();
  Eigen::Vector3d marker_rotation_std_rad = Eigen::Vector3d::Zero();
  double sigma_rad = 0.0;
  Eigen::VectorXd rotation_residuals_rad{};
  [[nodiscard]] bool ok() const { return status == MarkerOffsetStatus::kOk; }
};

/// Estimates T_robot_sensor and the marker offset p_flange_marker from J >= 5 poses:
/// T_robot_flange[j] the flange pose (forward kinematics, robot frame) [m], markers_sensor_m
/// column j the marker measured there [m, sensor frame]. Throws InputError on mismatched sizes,
/// fewer than 5 poses or non-finite values; an unobservable offset is a status, not an exception.
MarkerOffsetResult estimate_marker_offset(const std::vector<Eigen::Isometry3d>& T_robot_flange,
                                          const ConstPoints3Ref& markers_sensor_m,
                                          const MarkerOffsetOptions& options = {});

/// The same with the marker's orientation measured at every pose too: q_sensor_marker[j] the
/// marker frame's rotation in the sensor frame (unit quaternion; normalised here). Empty: as
/// above. The offset p still needs the flange orientations to vary (the rotation residuals do
/// not involve p or tau): the observability check is the same.
MarkerOffsetResult estimate_marker_offset(const std::vector<Eigen::Isometry3d>& T_robot_flange,
                                          const ConstPoints3Ref& markers_sensor_m,
                                          const std::vector<Eigen::Quaterniond>& q_sensor_marker,
                                          const MarkerOffsetOptions& options = {});

/// The orientation spread of a set of flange poses (see MarkerOffsetResult::orientation_spread).
double orientation_spread(const std::vector<Eigen::Isometry3d>& T_robot_flange);

}  // namespace vrreg
