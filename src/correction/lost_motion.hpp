// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to correction: lost motion (gear backlash and transmission compliance). Each joint j
// stops short of its command by beta_j / 2 against the direction s_j (-1, 0, +1) of its last move,
// so the reached position deviates from the commanded one by -J_pos(q) diag(s) beta / 2 (to first
// order; J_pos the position rows of the geometric Jacobian at the commanded joints). beta_j is the
// play the joint takes up (its lost motion times the take-up fraction), one parameter per joint.
#include <Eigen/Core>

#include "vrreg/core/types.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::detail {

/// Per-joint lost motion fitted by least squares, with its covariance.
struct LostMotionFit {
  Eigen::VectorXd beta_rad{};            ///< per joint: the play taken up [rad]
  Eigen::MatrixXd covariance_rad2{};     ///< of beta_rad [rad^2]
  Eigen::MatrixXd trend_coefficients{};  ///< 3 x terms of the polynomial trend fitted beside it
  double residual_sd_m = 0.0;            ///< per axis, of what both leave [m]
};

/// The deviations lost motion gives at commanded joints `joints_rad` (n_joints x N) arriving
/// with `approach_sign` (n_joints x N), for plays `beta_rad`: 3 x N, robot frame [m].
Points3 lost_motion_deviation_m(const kinematics::SerialChain& chain,
                                const Eigen::Ref<const Eigen::MatrixXd>& joints_rad,
                                const Eigen::Ref<const Eigen::MatrixXd>& approach_sign,
                                const Eigen::Ref<const Eigen::VectorXd>& beta_rad);

/// Fits beta jointly with a polynomial trend of degree `trend_degree` (0, 1 or 2) in the
/// positions `positions_m` (3 x N, robot frame) to the measured deviations `deviation_m`
/// (3 x N, reached minus commanded, robot frame): ordinary least squares over the three axes,
/// the covariance from the residual variance. Joints that never move (all signs 0) get beta 0
/// and variance 0. Throws InputError when sizes disagree or there are too few points.
LostMotionFit fit_lost_motion(const kinematics::SerialChain& chain,
                              const Eigen::Ref<const Eigen::MatrixXd>& joints_rad,
                              const Eigen::Ref<const Eigen::MatrixXd>& approach_sign,
                              const ConstPoints3Ref& positions_m,
                              const ConstPoints3Ref& deviation_m, int trend_degree = 2);

}  // namespace vrreg::detail
