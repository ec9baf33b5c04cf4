// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal: the pieces of the LWR 4+ arm-angle IK shared by the solver, the inverse map and the
// feasible-psi search. All angles here are DH angles theta = q + offset.
#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics::detail {

/// Link lengths of an LWR-structured chain [m] and its joint offsets [rad].
struct LwrGeometry {
  double d_bs = 0.0;  ///< base to shoulder (d1)
  double d_se = 0.0;  ///< shoulder to elbow (d3)
  double d_ew = 0.0;  ///< elbow to wrist (d5)
  double d_wf = 0.0;  ///< wrist to flange (d7)
  double offset[7] = {};
};

/// Throws InputError unless `chain` has the LWR structure.
LwrGeometry lwr_geometry(const SerialChain& chain, const char* what);

/// Everything about a flange pose that does not depend on psi. R03(psi) = As sin + Bs cos + Cs.
struct LwrPoseFrame {
  bool reachable = false;
  std::string message;  ///< why not reachable
  Eigen::Matrix3d r;    ///< flange rotation in the DH base frame
  Eigen::Vector3d u;    ///< unit shoulder-to-wrist axis
  double theta4 = 0.0;  ///< elbow angle of the base configuration, >= 0
  Eigen::Matrix3d r34;  ///< rotation of joint 4 at theta4
  Eigen::Matrix3d as, bs, cs;
  Eigen::Matrix3d r03_reference;           ///< psi = 0
  double offset3 = 0.0, offset7 = 0.0;     ///< joint offsets of joints 3 and 7 [rad]
  std::uint8_t singular = kNoSingularity;  ///< kElbowSingular, kArmAngleSingular
};

/// Pose analysis of T_dh0_flange; unreachable poses give reachable = false and a message.
LwrPoseFrame lwr_pose_frame(const LwrGeometry& g, const Eigen::Matrix3d& r_dh0_flange,
                            const Eigen::Vector3d& p_dh0_flange, double singular_tolerance,
                            double reach_tolerance_m);

/// R03 = P(theta1) M(theta2) M(theta3): the shoulder's rotation for DH angles theta1..3 [rad].
Eigen::Matrix3d lwr_shoulder_rotation(double theta1, double theta2, double theta3);

/// DH angles of the base configuration GC = (+, +, +) at arm angle psi.
struct LwrBaseSolution {
  double theta[7];
  std::uint8_t singular;  ///< pose flags plus kShoulderSingular, kWristSingular
};
LwrBaseSolution lwr_base_solution(const LwrPoseFrame& frame, double psi_rad,
                                  const IkOptions& options);

/// DH angles of global configuration `index` (bits 4: theta2 < 0, 2: theta4 < 0, 1: theta6 < 0)
/// from the base configuration by the flips of design.md section 4, wrapped to (-pi, pi].
void lwr_flip(const double base[7], int index, double out[7]);

/// lwr_flip for all eight indices at once (out[index]), with the same bits: each joint takes one
/// of at most three values (as is, flipped once, flipped twice), each wrapped once.
void lwr_flips(const double base[7], double out[8][7]);

}  // namespace vrreg::kinematics::detail
