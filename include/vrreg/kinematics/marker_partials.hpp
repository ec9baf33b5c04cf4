// SPDX-License-Identifier: Apache-2.0
#pragma once
// Partial derivatives of a marker point's robot-frame position with respect to the joint angles
// and the standard DH parameters (a, d, alpha) of every row and the marker's flange offset: the
// identification Jacobian of kinematic calibration (Mooring, Roth & Driels, "Fundamentals of
// Manipulator Calibration", 1991, ch. 4; Hollerbach & Wampler, IJRR 15(6), 1996).
#include <Eigen/Core>

#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// Marker position and its first derivatives at one joint vector; base = robot frame, SI units.
struct MarkerPartials {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< p = T_base_flange(q) p_flange_marker
  /// R_base_flange(q): d p / d p_flange_marker [m/m].
  Eigen::Matrix3d R_base_flange = Eigen::Matrix3d::Identity();
  /// 3 x n_joints(), column i: d p / d q_i of joint variable i [m/rad; prismatic: m/m]
  Eigen::Matrix3Xd d_joint{};
  Eigen::Matrix3Xd d_theta{};  ///< 3 x n_rows(), column i: d p / d theta_offset_i [m/rad]
  Eigen::Matrix3Xd d_a{};      ///< 3 x n_rows(), column i: d p / d a_i [m/m]
  Eigen::Matrix3Xd d_d{};      ///< 3 x n_rows(), column i: d p / d d_i [m/m]
  Eigen::Matrix3Xd d_alpha{};  ///< 3 x n_rows(), column i: d p / d alpha_i [m/rad]
};

/// Position of the marker at `p_flange_marker_m` (flange = last DH frame) and its partials at
/// joints `q_rad`, analytic: row i maps frame i-1 to i by Rz(theta) Tz(d) Tx(a) Rx(alpha), so
/// theta and d act along z_{i-1} about/through o_{i-1}, a and alpha along/about x_i through o_i.
/// The chain's tool transform is not used (the marker replaces it); its base transform is.
MarkerPartials marker_partials(const SerialChain& chain, const JointRef& q_rad,
                               const Eigen::Vector3d& p_flange_marker_m);

}  // namespace vrreg::kinematics
