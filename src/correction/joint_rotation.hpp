// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to correction: what the joint-space model fitted on positions leaves of the fiducials'
// orientation errors, as joint-angle errors and link rotations seen by orientations only (e.g.
// the last joint's offset, the wrist's twist errors, with the marker near the wrist's axes):
// g(q) = sum_i z_i(q) dq_i(q_i) + sum_i R_base_i(q) r_i, z_i the axis of revolute joint i in the
// base frame, dq_i a Legendre series over the joint's fitted range (one degree for every joint)
// plus the cyclic terms a periodogram finds, and r_i link i's constant rotation in its own frame;
// the degree, whether the links' rotations enter and whether the cyclic terms do chosen by K-fold
// cross-validation (first order in dq and r).
#include <Eigen/Core>
#include <cstdint>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/orientation_field.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::detail {

/// g(q) [rad, robot frame] of `terms` on `chain` (the nominal arm to the marker).
/// `dq_rad`: the positions' joint-angle errors at q, needed when the terms scale them.
Eigen::Vector3d joint_rotation_rad(const JointRotationTerms& terms,
                                   const kinematics::SerialChain& chain,
                                   const Eigen::Ref<const Eigen::VectorXd>& q_rad,
                                   const Eigen::VectorXd* dq_rad = nullptr);

/// Throws InputError when the terms' sizes do not fit `n_joints`.
void validate_joint_rotation(const JointRotationTerms& terms, int n_joints);

/// What fit_joint_rotation chose, with its cross-validated RMS and the combinations it kept.
struct JointRotationFit {
  JointRotationTerms terms{};
  double cv_rms_rad = 0.0;  ///< RMS angle of the held-out fiducials' g - prediction [rad]
  int columns = 0;          ///< the chosen design's columns (the constant's 3 included)
  int rank = 0;             ///< combinations kept: the others were not identifiable
};

/// The strongest cyclic joint-angle error in `residual_robot_rad` (3 x J) at joints `joints_rad`
/// (n x J): joint i's term z_i(q) (s sin(w q_i) + c cos(w q_i)) that lowers the residual's sum of
/// squares most (`drop`, rad^2), over frequencies from one period in the joint's range to the
/// mean Nyquist rate of its distinct angles; joint -1 when no joint has 8 distinct angles.
/// `n_candidates`: the frequencies tried, for the false-alarm threshold.
struct PeriodicPeak {
  int joint = -1;
  double omega_per_rad = 0.0;
  double drop = 0.0;
  int n_candidates = 0;
};
PeriodicPeak strongest_periodic_term(const kinematics::SerialChain& chain,
                                     const Eigen::MatrixXd& joints_rad,
                                     const Points3& residual_robot_rad);

/// Fits g to `g_robot_rad` (3 x J) at joints `joints_rad` (n x J) jointly with a constant
/// rotation (left to the caller's mean residual), choosing the degree among -1 (none), 0, 1, 2,
/// 4, 6, 8, with or without the links' rotations, and the singular values kept (truncated SVD,
/// minimum norm: a fixed tool orientation makes many combinations indistinguishable) by
/// `folds`-fold cross-validation (seeded shuffle); then adds the cyclic joint-angle errors a
/// greedy periodogram of what that choice leaves finds above noise (false-alarm rate 1e-3 over
/// all the frequencies tried), the choice made again with them, kept when it cross-validates
/// better.
/// `dq_rad` (n x J, when given): the positions' joint-angle errors at the fiducials, each joint's
/// along its axis a column of its own (PositionRotation::kScaledJointAngles).
JointRotationFit fit_joint_rotation(const kinematics::SerialChain& chain,
                                    const Eigen::MatrixXd& joints_rad, const Points3& g_robot_rad,
                                    const Eigen::MatrixXd* dq_rad = nullptr, int folds = 5,
                                    std::uint64_t seed = 1);

}  // namespace vrreg::detail
