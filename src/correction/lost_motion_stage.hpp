// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to correction: the lost-motion term as a corrector's first stage (lost_motion.hpp
// fits it). The plays are fitted on the fiducials' corrections, the term is subtracted, the
// method fits what is left; a query gets the method's correction plus the term at its joints and
// approach directions, and the term's uncertainty added to the sd in quadrature.
#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/correction_method.hpp"
#include "vrreg/correction/corrector_data.hpp"
#include "vrreg/correction/lost_motion_term.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::detail {

/// Why the term cannot be fitted on `data` (no joints, robot or approach directions, or no
/// joint approached from both sides), or empty when it can.
std::string lost_motion_unavailable(const CorrectorData& data);

/// The corrections (Eq. 6, sensor frame [m]) the term with plays `play_rad` gives at commanded
/// joints `joints_rad` arriving with `approach_sign` (n_joints x N each): the robot-frame
/// deviation -J diag(s) beta / 2 mapped back through the registration's rotation and scale.
Points3 lost_motion_correction_sensor_m(const kinematics::SerialChain& chain,
                                        const SimilarityTransform& T_robot_sensor,
                                        const Eigen::Ref<const Eigen::MatrixXd>& joints_rad,
                                        const Eigen::Ref<const Eigen::MatrixXd>& approach_sign,
                                        const Eigen::Ref<const Eigen::VectorXd>& play_rad);

/// `data` with the term of plays `play_rad` taken out of its corrections: what the method fits.
CorrectorData without_lost_motion(const CorrectorData& data,
                                  const Eigen::Ref<const Eigen::VectorXd>& play_rad);

/// Fits the plays on all of `data` (lost_motion_unavailable must be empty) and decides whether
/// the term enters: kOn always; kAuto when the K-fold cross-validation (the folds of `folds`,
/// `seed`, the term refitted in each fold) of the judge (LostMotionTerm::judged_by: the joint
/// model for a `requested` auto or joint on cells of up to 3 000 fiducials, its plays then fitted
/// beside the joint model; else the cheapest field model that fits, trilinear or RBF, its plays
/// beside a quadratic trend) with the term beats it without the term by the margin in the .cpp,
/// on the held-out fiducials both predicted. Throws InputError when the plays cannot be fitted
/// (too few fiducials for the parameters).
LostMotionTerm fit_lost_motion_term(const CorrectorData& data, LostMotionMode mode,
                                    const MethodSettings& settings, int folds, std::uint64_t seed,
                                    InterpolationMethod requested = InterpolationMethod::kTrilinear);

/// The term at query points: corrections (sensor frame [m], 3 x N) and the variance (3D [m^2])
/// it adds to a corrected point's error. `approach_sign` n_joints x N, or 0 x 0 when unknown; a
/// 0 entry (unknown direction) takes the mean over both directions (none) and adds the whole
/// term of that joint, |J_j beta_j| / 2, to the variance.
struct LostMotionPrediction {
  Points3 corrections_sensor_m{};
  Eigen::VectorXd variance_m2{};
};
LostMotionPrediction predict_lost_motion(const kinematics::SerialChain& chain,
                                         const SimilarityTransform& T_robot_sensor,
                                         const LostMotionTerm& term,
                                         const Eigen::Ref<const Eigen::MatrixXd>& joints_rad,
                                         const Eigen::Ref<const Eigen::MatrixXd>& approach_sign);

}  // namespace vrreg::detail
