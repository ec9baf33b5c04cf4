// SPDX-License-Identifier: Apache-2.0
#pragma once
// RRBC for orientations (beyond the paper; docs/orientation.md): a tracked rigid body gives each
// fiducial an orientation besides its position. Positions are registered as before (Eq. 2); each
// fiducial also gets a rotation residual, the rotation D_j = R_cmd_j (R R_sensor_marker_j)^T that
// takes its registered measured orientation to the commanded one (the analogue of Eq. 6). The
// residuals are interpolated as the positions' corrections are (Eq. 7), on the tangent space of
// SO(3) at their mean M: v_j = log(D_j M^T), D(T) = exp(v(T)) M; a target's corrected orientation
// is D(T) R R_sensor_marker_T (the analogue of Eq. 8). The joint-space model predicts the arm's
// orientation error from the joints instead.
#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/corrector.hpp"
#include "vrreg/correction/corrector_data.hpp"
#include "vrreg/correction/rrbc.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg {

/// The fiducials' rotation residuals (the orientation analogue of Eq. 6), robot frame [rad]:
/// log(R_robot_marker_j (R_robot_sensor R_sensor_marker_j)^T), one column each, with
/// R_robot_marker_j the commanded orientation and R_sensor_marker_j the measured one. Throws
/// InputError when the counts differ.
Points3 rotation_residuals_rad(const Eigen::Matrix3d& R_robot_sensor,
                               std::span<const Eigen::Matrix3d> R_sensor_marker,
                               std::span<const Eigen::Matrix3d> R_robot_marker);

/// Corrected orientations of n targets; every per-target member has n entries.
struct OrientationCorrection {
  InterpolationMethod method_used = InterpolationMethod::kLinear;
  std::vector<StencilStatus> status{};  ///< as the positions' stencils: kOk or why not corrected
  std::vector<Eigen::Matrix3d> uncorrected_R_robot_marker{};  ///< R R_sensor_marker
  /// D(T) R R_sensor_marker where corrected, the uncorrected orientation where not.
  std::vector<Eigen::Matrix3d> corrected_R_robot_marker{};
  Points3 corrections_robot_rad{};  ///< log D(T), robot frame [rad]; 0 where not corrected
  /// The predicted standard uncertainty of each corrected orientation's angle error [rad]
  /// (NaN where not corrected); empty for the paper's stencils.
  Eigen::VectorXd predicted_sd_rad{};
  int n_flagged = 0;  ///< targets not corrected
  /// A predicted sd above this is flagged (default: the fiducials' uncorrected RMS angle, what
  /// no correction would leave) [rad]; 0: none set.
  double sd_limit_rad = 0.0;
  /// Whether target t's predicted sd is above sd_limit_rad (false without a limit or an sd).
  [[nodiscard]] bool sd_over_limit(std::size_t t) const {
    return sd_limit_rad > 0.0 && t < static_cast<std::size_t>(predicted_sd_rad.size()) &&
           predicted_sd_rad(static_cast<Eigen::Index>(t)) > sd_limit_rad;
  }
};

/// Which part of the positions' joint model's rotation the orientation's joint model uses.
/// kScaledJointAngles: each joint's fitted angle error dq_i(q) along its axis as a term of its
/// own, scaled by a fitted factor (1 where positions determine the joint, 0 where they do not).
enum class PositionRotation { kNone, kFull, kJointAngles, kScaledJointAngles };
/// "none", "full", "joint_angles", "scaled_joint_angles" (model files); parse throws InputError
/// on another name.
const char* to_string(PositionRotation which);
PositionRotation parse_position_rotation(const std::string& name);

/// The joint model's orientation-only terms: joint-angle errors and link rotations that
/// positions do not show (e.g. the last joint's offset, the wrist's twist errors, with the marker
/// near the wrist's axes), fitted on what the position model leaves of the fiducials'
/// orientations: g(q) = sum_i z_i(q) dq_i(q_i) + sum_i R_base_i(q) r_i, z_i the axis of revolute
/// joint i, dq_i a Legendre series of `degree` over the joint's fitted range [q_lo, q_hi]
/// (degree -1: none) plus any periodic terms of joint i, and r_i link i's rotation in its own
/// frame.
struct JointRotationTerms {
  int degree = -1;
  Eigen::VectorXd q_lo_rad{};
  Eigen::VectorXd q_hi_rad{};
  Eigen::VectorXd coefficients{};  ///< joint-major, n_joints x (degree + 1) [rad]
  /// Each link's constant small rotation in its own frame (frames 1..n, 3 each) [rad], which
  /// positions hardly show when the marker is near the wrist's axes: g(q) += sum_i R_base_i(q)
  /// r_i. Empty: none.
  Eigen::VectorXd link_rotations_rad{};
  /// What of the positions' joint model's rotation e(q) enters, D(q) = exp(-(e + g)(q)) M, by
  /// cross-validation: all of it, its joint-angle errors' part only, or none (exp(-g(q)) M). A
  /// fixed tool orientation leaves combinations of the DH deltas that positions cannot tell
  /// apart, and their rotations wrong.
  PositionRotation position_rotation = PositionRotation::kFull;
  /// A constant rotation fitted jointly with the terms above [rad, robot frame]: with a fixed
  /// tool orientation the last links' rotations are constants too, and only their sum with it
  /// is determined. Zero in files written before it.
  Eigen::Vector3d constant_rad = Eigen::Vector3d::Zero();
  /// kScaledJointAngles: the factor of each joint's dq_i(q) term (n_joints); empty otherwise.
  Eigen::VectorXd position_joint_scales{};
  /// Cyclic joint-angle errors that only orientations show (a wrist joint's transmission error,
  /// which hardly moves a marker near the wrist's axes): term m adds z_i(q) (s_m sin(w_m q_i) +
  /// c_m cos(w_m q_i)), i = periodic[m].joint, found by a periodogram of what the smooth terms
  /// leave and kept when cross-validation says so. Empty: none.
  std::vector<kinematics::JointPeriodicTerm> periodic{};
  Eigen::VectorXd periodic_coefficients{};  ///< s_m, c_m of each periodic term [rad]
  /// The design's columns and the combinations the fit kept (truncated SVD); 0 when unknown.
  int columns = 0;
  int rank = 0;
};

/// One method's cross-validation of the orientations: RMS angle of the held-out fiducials'
/// rotation residual against its prediction, the fiducials a method cannot predict counted at
/// their uncorrected angle (so a method is not ranked on the interior alone).
struct OrientationCvRow {
  InterpolationMethod method = InterpolationMethod::kLinear;
  bool applicable = false;  ///< false: `note` says why
  std::string note{};
  double rms_rad = 0.0;          ///< over every fiducial [rad]
  Eigen::Index n_predicted = 0;  ///< fiducials the held-out models predicted
};

/// An orientation field's saved form: what restore() needs besides the fiducials, their rotation
/// residuals and the positions' corrector.
struct SavedOrientationCorrector {
  InterpolationMethod method = InterpolationMethod::kLinear;
  /// False: no method's cross-validated RMS angle was below the uncorrected one, and every
  /// target keeps its uncorrected orientation (StencilStatus::kNotBetterThanNone).
  bool applied = true;
  double uncorrected_rms_rad = 0.0;  ///< RMS angle of the fiducials' rotation residuals [rad]
  double cv_rms_rad = 0.0;  ///< the method's cross-validated RMS angle [rad]; 0: not known
  std::vector<OrientationCvRow> cross_validation{};  ///< the methods compared (auto), or the one
  Eigen::Matrix3d mean_residual = Eigen::Matrix3d::Identity();  ///< M
  double joint_rms_rad = 0.0;               ///< the joint model's predicted sd [rad]
  JointRotationTerms joint_terms{};         ///< the joint model's orientation-only terms
  std::optional<SavedCorrector> tangent{};  ///< every method but the joint model
};

/// An orientation field fitted on one registration's fiducials: immutable, thread-safe, cheap to
/// copy, like the positions' Corrector.
class OrientationCorrector {
 public:
  /// Fits the orientation field on the fiducials of `data` with rotation residuals
  /// `residuals_robot_rad` (3 x J), with the method `positions` was asked for; `auto` chooses
  /// by the orientations' own cross-validation (OrientationCvRow), which may differ from the
  /// positions' choice. The joint model predicts the orientation error from the joints (the
  /// positions' joint model when it helps, the terms only orientations show, and the mean of
  /// what they leave: the registration's rotation error); every other method interpolates the
  /// residuals on the tangent space at their mean. A field whose cross-validated RMS angle is
  /// not below the uncorrected one is kept but not applied (applied()).
  /// `noise_sd_rad`: the noise of one fiducial's averaged orientation per axis, when known. Throws
  /// InputError when the method cannot be used.
  static OrientationCorrector fit(const Corrector& positions, const CorrectorData& data,
                                  const ConstPoints3Ref& residuals_robot_rad,
                                  std::optional<double> noise_sd_rad = std::nullopt);

  /// The field `saved` describes, on the fiducials, residuals and positions' corrector it was
  /// fitted with, without fitting: it corrects with the same bits. Throws InputError when the
  /// saved state does not fit them.
  static OrientationCorrector restore(const SavedOrientationCorrector& saved,
                                      const Corrector& positions, const CorrectorData& data,
                                      const ConstPoints3Ref& residuals_robot_rad,
                                      std::optional<double> noise_sd_rad = std::nullopt);
  [[nodiscard]] SavedOrientationCorrector save() const;

  /// Corrects the orientations `R_sensor_marker` (one per point of `query`, measured) of the
  /// points of `query` (as for the positions' Corrector::correct). Throws InputError on a count
  /// mismatch or what the method needs and the query lacks. `positions_answer`: the positions'
  /// correction of the same query when the caller has it; the joint model then reads where it
  /// holds from it instead of correcting the positions again.
  [[nodiscard]] OrientationCorrection correct(
      const CorrectionQuery& query, std::span<const Eigen::Matrix3d> R_sensor_marker,
      const TargetCorrection* positions_answer = nullptr) const;

  [[nodiscard]] InterpolationMethod method() const { return method_; }
  /// False: cross-validation found the field no better than no correction; correct() then
  /// answers every target uncorrected with StencilStatus::kNotBetterThanNone.
  [[nodiscard]] bool applied() const { return applied_; }
  /// The fiducials' RMS rotation residual angle, uncorrected [rad].
  [[nodiscard]] double uncorrected_rms_rad() const { return uncorrected_rms_rad_; }
  /// The method's cross-validated RMS angle [rad] (0 when not known: a model file without it).
  [[nodiscard]] double cv_rms_rad() const { return cv_rms_rad_; }
  /// The methods compared (auto), or the one fitted.
  [[nodiscard]] const std::vector<OrientationCvRow>& cross_validation() const { return table_; }
  /// What was fitted, e.g. "kriging ..., about the mean rotation 0.41 mrad".
  [[nodiscard]] std::string describe() const;
  /// The mean rotation residual M (joint model: of what the model leaves).
  [[nodiscard]] const Eigen::Matrix3d& mean_residual() const { return mean_; }
  /// True when correct() fills predicted_sd_rad.
  [[nodiscard]] bool predicts_sd() const;
  /// The registration the residuals were computed with (Eq. 2).
  [[nodiscard]] const SimilarityTransform& T_robot_sensor() const { return T_robot_sensor_; }

 private:
  OrientationCorrector() = default;
  /// Support of the joint terms fitted without the positions' joint model: inside the fiducials'
  /// joint ranges (with the joint model's margins), else outside support.
  [[nodiscard]] std::vector<StencilStatus> joint_support(const CorrectionQuery& query) const;
  InterpolationMethod method_ = InterpolationMethod::kLinear;
  bool applied_ = true;
  double uncorrected_rms_rad_ = 0.0;
  double cv_rms_rad_ = 0.0;
  std::vector<OrientationCvRow> table_{};
  SimilarityTransform T_robot_sensor_{};
  Eigen::Matrix3d mean_ = Eigen::Matrix3d::Identity();
  /// Every method but the joint model: fitted on the tangent residuals v_j.
  std::optional<Corrector> tangent_{};
  /// The joint model: the positions' corrector when it is the joint model (its rotation
  /// prediction e(q), when it enters, and its support), the terms g(q) only orientations show,
  /// on the arm `joint_chain_`, and the RMS angle of what they leave at the fiducials [rad], its
  /// predicted sd: D(q) = exp(-(e(q) + g(q))) M.
  bool joint_model_ = false;
  std::optional<Corrector> joint_{};
  JointRotationTerms joint_terms_{};
  std::optional<kinematics::SerialChain> joint_chain_{};
  double joint_rms_rad_ = 0.0;
};

}  // namespace vrreg
