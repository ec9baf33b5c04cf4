// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/orientation_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "joint_rotation.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/rotation.hpp"

namespace vrreg {
namespace {

std::vector<Eigen::Matrix3d> residual_rotations(const ConstPoints3Ref& residuals_robot_rad) {
  std::vector<Eigen::Matrix3d> out;
  out.reserve(static_cast<std::size_t>(residuals_robot_rad.cols()));
  for (Eigen::Index j = 0; j < residuals_robot_rad.cols(); ++j) {
    out.push_back(rotation_exp(residuals_robot_rad.col(j)));
  }
  return out;
}

void check_inputs(const CorrectorData& data, const ConstPoints3Ref& residuals_robot_rad,
                  std::optional<double> noise_sd_rad) {
  data.validate();
  VRREG_THROW_UNLESS(residuals_robot_rad.cols() == data.size(),
                     "orientation field: " << residuals_robot_rad.cols()
                                           << " rotation residuals for " << data.size()
                                           << " fiducials");
  VRREG_THROW_UNLESS(residuals_robot_rad.allFinite(),
                     "orientation field: a rotation residual is not finite");
  VRREG_THROW_UNLESS(!noise_sd_rad || (std::isfinite(*noise_sd_rad) && *noise_sd_rad >= 0.0),
                     "orientation field: the orientation noise must be finite and >= 0");
}

// The fiducials as the tangent field sees them: v_j = log(D_j M^T) in place of the corrections.
CorrectorData tangent_data(const CorrectorData& data, const std::vector<Eigen::Matrix3d>& rotations,
                           const Eigen::Matrix3d& mean, std::optional<double> noise_sd_rad) {
  CorrectorData tangent = data;
  for (Eigen::Index j = 0; j < tangent.size(); ++j) {
    tangent.corrections_sensor_m.col(j) =
        rotation_log(rotations[static_cast<std::size_t>(j)] * mean.transpose());
  }
  tangent.noise_sd_m = noise_sd_rad;
  tangent.values = CorrectionValues::kRotationRad;
  tangent.approach_sign.resize(0, 0);  // lost motion is a position term: no stage on rotations
  return tangent;
}

}  // namespace

const char* to_string(PositionRotation which) {
  switch (which) {
    case PositionRotation::kNone: return "none";
    case PositionRotation::kFull: return "full";
    case PositionRotation::kJointAngles: return "joint_angles";
    case PositionRotation::kScaledJointAngles: return "scaled_joint_angles";
  }
  return "full";
}

PositionRotation parse_position_rotation(const std::string& name) {
  for (const PositionRotation p : {PositionRotation::kNone, PositionRotation::kFull,
                                   PositionRotation::kJointAngles,
                                   PositionRotation::kScaledJointAngles}) {
    if (name == to_string(p)) return p;
  }
  VRREG_THROW_UNLESS(false, "position rotation '"
                                << name
                                << "': expected none, full, joint_angles or scaled_joint_angles");
  return PositionRotation::kFull;
}

Points3 rotation_residuals_rad(const Eigen::Matrix3d& R_robot_sensor,
                               std::span<const Eigen::Matrix3d> R_sensor_marker,
                               std::span<const Eigen::Matrix3d> R_robot_marker) {
  VRREG_THROW_UNLESS(R_sensor_marker.size() == R_robot_marker.size(),
                     "rotation residuals: " << R_sensor_marker.size()
                                            << " measured orientations but "
                                            << R_robot_marker.size() << " commanded ones");
  Points3 out(3, static_cast<Eigen::Index>(R_sensor_marker.size()));
  for (std::size_t j = 0; j < R_sensor_marker.size(); ++j) {
    VRREG_THROW_UNLESS(R_sensor_marker[j].allFinite() && R_robot_marker[j].allFinite(),
                       "rotation residuals: orientation " << j << " is not finite");
    out.col(static_cast<Eigen::Index>(j)) =
        rotation_log(R_robot_marker[j] * (R_robot_sensor * R_sensor_marker[j]).transpose());
  }
  return out;
}

namespace {

// Joint ranges a commanded joint may leave by this share of the range (plus a milliradian)
// before the orientation's joint terms are outside their support: the joint model's margins.
constexpr double kJointRangeMargin = 0.05;
constexpr double kJointSlackRad = 1e-3;

double rms_angle_rad(const ConstPoints3Ref& residuals_robot_rad) {
  return residuals_robot_rad.cols() == 0
             ? 0.0
             : std::sqrt(residuals_robot_rad.colwise().squaredNorm().sum() /
                         static_cast<double>(residuals_robot_rad.cols()));
}

// A tangent field's cross-validation row as the orientations rank it: the fiducials it could not
// predict count at their uncorrected angle.
OrientationCvRow orientation_row(const CrossValidationRow& row,
                                 const ConstPoints3Ref& residuals_robot_rad) {
  OrientationCvRow out;
  out.method = row.method;
  out.applicable = row.applicable;
  out.note = row.note;
  out.n_predicted = row.n_predicted;
  if (!row.applicable) return out;
  double sum = 0.0;
  for (Eigen::Index j = 0; j < residuals_robot_rad.cols(); ++j) {
    const double e = row.squared_error_m2.size() == residuals_robot_rad.cols()
                         ? row.squared_error_m2(j)
                         : std::numeric_limits<double>::quiet_NaN();
    sum += std::isnan(e) ? residuals_robot_rad.col(j).squaredNorm() : e;
  }
  out.rms_rad = std::sqrt(sum / static_cast<double>(residuals_robot_rad.cols()));
  return out;
}

// The joint model's orientation terms fitted with e(q) (when `positions` is the joint model)
// and without, the better by cross-validation.
struct JointOrientationFit {
  detail::JointRotationFit fit{};
  std::vector<Eigen::Vector3d> e{};  ///< e(q_j), zero when it does not enter
  std::optional<Eigen::MatrixXd> dq_rad{};  ///< dq(q_j) when the terms scale them
};

JointOrientationFit fit_joint_orientation(const Corrector* positions, const CorrectorData& data,
                                          const std::vector<Eigen::Matrix3d>& rotations) {
  const auto n = static_cast<std::size_t>(data.size());
  std::optional<JointOrientationFit> best;
  for (const PositionRotation which :
       {PositionRotation::kFull, PositionRotation::kJointAngles,
        PositionRotation::kScaledJointAngles, PositionRotation::kNone}) {
    if (which != PositionRotation::kNone && positions == nullptr) continue;
    const bool with_e =
        which == PositionRotation::kFull || which == PositionRotation::kJointAngles;
    JointOrientationFit candidate;
    candidate.e.assign(n, Eigen::Vector3d::Zero());
    std::vector<Eigen::Matrix3d> left(n);
    for (std::size_t j = 0; j < n; ++j) {
      if (with_e) {
        const std::optional<Eigen::Vector3d> e_j =
            positions->rotation_error_rad(data.joints_rad.col(static_cast<Eigen::Index>(j)),
                                          which == PositionRotation::kJointAngles);
        VRREG_THROW_UNLESS(e_j, "orientation field: the joint model predicts no rotation");
        candidate.e[j] = *e_j;
      }
      left[j] = rotation_exp(candidate.e[j]) * rotations[j];
    }
    // The residual D_j = exp(-e(q_j)) exp(-g(q_j)) C, C the registration's rotation error (and
    // the marker's misalignment); g to the first order about C's estimate C0.
    const Eigen::Matrix3d C0 = rotation_mean(left);
    Points3 g(3, data.size());
    for (std::size_t j = 0; j < n; ++j) {
      g.col(static_cast<Eigen::Index>(j)) = -rotation_log(left[j] * C0.transpose());
    }
    if (which == PositionRotation::kScaledJointAngles) {
      Eigen::MatrixXd& dq = candidate.dq_rad.emplace(data.joints_rad.rows(), data.size());
      for (Eigen::Index j = 0; j < data.size(); ++j) {
        dq.col(j) = *positions->joint_angle_errors_rad(data.joints_rad.col(j));
      }
    }
    candidate.fit = detail::fit_joint_rotation(*data.robot, data.joints_rad, g,
                                               candidate.dq_rad ? &*candidate.dq_rad : nullptr);
    candidate.fit.terms.position_rotation = which;
    if (!best || candidate.fit.cv_rms_rad < best->fit.cv_rms_rad) best = std::move(candidate);
  }
  return std::move(*best);
}

}  // namespace

OrientationCorrector OrientationCorrector::fit(const Corrector& positions,
                                               const CorrectorData& data,
                                               const ConstPoints3Ref& residuals_robot_rad,
                                               std::optional<double> noise_sd_rad) {
  check_inputs(data, residuals_robot_rad, noise_sd_rad);
  OrientationCorrector out;
  out.T_robot_sensor_ = data.T_robot_sensor;
  out.uncorrected_rms_rad_ = rms_angle_rad(residuals_robot_rad);
  const std::vector<Eigen::Matrix3d> rotations = residual_rotations(residuals_robot_rad);
  const InterpolationMethod requested = positions.requested().method;
  const bool positions_joint = positions.method() == InterpolationMethod::kJoint;
  const bool joints_known = data.has_joints() && data.robot.has_value();

  // Candidates: the joint model (when asked for, or auto with joints) and the tangent fields.
  std::optional<JointOrientationFit> joint;
  // The orientation terms are per DH row, the commanded joints per variable: a chain with
  // coupled (URDF mimic) rows would pair them wrongly.
  const bool coupled = joints_known && data.robot->coupled();
  VRREG_THROW_UNLESS(!(requested == InterpolationMethod::kJoint && coupled),
                     "orientation field: the joint model does not take coupled (mimic) joints; "
                     "register with --interpolation auto or kriging to correct orientations");
  if (requested == InterpolationMethod::kAuto && coupled) {
    OrientationCvRow row;
    row.method = InterpolationMethod::kJoint;
    row.note = "the robot has coupled (mimic) joints";
    out.table_.push_back(row);
  }
  if (requested == InterpolationMethod::kJoint ||
      (requested == InterpolationMethod::kAuto && joints_known && !coupled)) {
    VRREG_THROW_UNLESS(joints_known, "orientation field: the joint model needs joints and the robot");
    joint = fit_joint_orientation(positions_joint ? &positions : nullptr, data, rotations);
    OrientationCvRow row;
    row.method = InterpolationMethod::kJoint;
    row.applicable = true;
    row.rms_rad = joint->fit.cv_rms_rad;
    row.n_predicted = data.size();
    out.table_.push_back(row);
  }
  out.mean_ = rotation_mean(rotations);
  CorrectorData tangent = tangent_data(data, rotations, out.mean_, noise_sd_rad);
  CorrectorOptions options;
  options.lost_motion = LostMotionMode::kOff;
  options.interpolation = positions.requested();
  options.nearest_configuration = positions.nearest_configuration();
  options.tabulate = positions.tabulated();
  options.guard = false;  // the orientations judge themselves (OrientationCorrector::applied)
  std::optional<Corrector> field;
  if (requested == InterpolationMethod::kAuto) {
    // The Cartesian candidates only: the joint-space position model does not apply to rotation
    // vectors (the joint model of orientations is the candidate above).
    CorrectorData cartesian = tangent;
    cartesian.joints_rad.resize(0, 0);
    cartesian.robot.reset();
    field = Corrector::fit(cartesian, options);
    for (const CrossValidationRow& row : field->cross_validation()->rows) {
      if (row.method == InterpolationMethod::kJoint) continue;
      out.table_.push_back(orientation_row(row, residuals_robot_rad));
    }
    const OrientationCvRow* best = nullptr;
    for (const OrientationCvRow& row : out.table_) {
      if (row.applicable && (best == nullptr || row.rms_rad < best->rms_rad)) best = &row;
    }
    VRREG_THROW_UNLESS(best != nullptr, "orientation field: no method could be cross-validated");
    out.method_ = best->method;
    out.cv_rms_rad_ = best->rms_rad;
    if (out.method_ == InterpolationMethod::kJoint) {
      field.reset();
    } else {
      joint.reset();
      if (out.method_ != field->method()) {  // ranked otherwise than the positions' rule
        options.interpolation.method = out.method_;
        field = Corrector::fit(cartesian, options);
      }
      // A tangent field without joints answers as the positions' Cartesian methods do.
      tangent = std::move(cartesian);
    }
  } else if (requested != InterpolationMethod::kJoint) {
    options.interpolation.method = requested;
    field = Corrector::fit(tangent, options);
    out.method_ = field->method();
    // The method's own cross-validation, for the guard: the same folds as the positions'.
    const std::vector<Eigen::Index> units = fold_units(tangent.fiducials_robot_m);
    const std::vector<int> folds = assign_folds(units, options.cv_folds, options.cv_seed);
    const MethodSettings settings{options.interpolation.cube_edge_m,
                                  options.interpolation.match_tolerance_m,
                                  options.nearest_configuration};
    out.table_.push_back(orientation_row(
        cross_validate(out.method_, tangent, settings, folds, units, options.cv_folds),
        residuals_robot_rad));
    if (!out.table_.back().applicable) {
      // The paper's stencils need a whole lattice or cube, which a fold's training set is not:
      // they are judged by trilinear interpolation of the same layout, their field-model kin.
      out.table_.push_back(orientation_row(cross_validate(InterpolationMethod::kTrilinear,
                                                          tangent, settings, folds, units,
                                                          options.cv_folds),
                                           residuals_robot_rad));
    }
    // Not judged (no method could be cross-validated on this layout): applied, as the paper's.
    out.cv_rms_rad_ = out.table_.back().applicable ? out.table_.back().rms_rad : 0.0;
  } else {
    out.method_ = InterpolationMethod::kJoint;
    out.cv_rms_rad_ = joint->fit.cv_rms_rad;
  }
  out.applied_ = out.cv_rms_rad_ == 0.0 || out.cv_rms_rad_ < out.uncorrected_rms_rad_;
  if (field) {
    out.tangent_ = std::move(field);
    return out;
  }
  // The joint model: what it leaves at the fiducials is its sd; their mean is M.
  out.joint_model_ = true;
  if (positions_joint) out.joint_ = positions;
  out.joint_chain_ = data.robot;
  out.joint_terms_ = joint->fit.terms;
  out.joint_terms_.columns = joint->fit.columns;
  out.joint_terms_.rank = joint->fit.rank;
  const auto n = static_cast<std::size_t>(data.size());
  std::vector<Eigen::Matrix3d> model(n);
  std::vector<Eigen::Matrix3d> left(n);
  for (std::size_t j = 0; j < n; ++j) {
    const auto col = static_cast<Eigen::Index>(j);
    // As fitted: D_j = exp(-e_j) exp(-g_j) C, composed rather than summed, since e(q) may be
    // radians (DH deltas positions cannot tell apart) that g(q) takes back.
    // The joint-angle errors the fit scaled, computed once there.
    const std::optional<Eigen::VectorXd> dq =
        joint->dq_rad ? std::optional<Eigen::VectorXd>(joint->dq_rad->col(col)) : std::nullopt;
    model[j] = rotation_exp(-joint->e[j]) *
               rotation_exp(-detail::joint_rotation_rad(out.joint_terms_, *data.robot,
                                                        data.joints_rad.col(col),
                                                        dq ? &*dq : nullptr));
    left[j] = model[j].transpose() * rotations[j];
  }
  out.mean_ = rotation_mean(left);
  double sum_sq = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    sum_sq += std::pow(rotation_angle_rad(model[j] * out.mean_, rotations[j]), 2);
  }
  // The sd: what the model leaves at the fiducials, or its cross-validated RMS when larger
  // (what it leaves at points it was not fitted to).
  out.joint_rms_rad_ = std::max(std::sqrt(sum_sq / static_cast<double>(n)), joint->fit.cv_rms_rad);
  return out;
}

OrientationCorrector OrientationCorrector::restore(const SavedOrientationCorrector& saved,
                                                   const Corrector& positions,
                                                   const CorrectorData& data,
                                                   const ConstPoints3Ref& residuals_robot_rad,
                                                   std::optional<double> noise_sd_rad) {
  check_inputs(data, residuals_robot_rad, noise_sd_rad);
  const InterpolationMethod requested = positions.requested().method;
  VRREG_THROW_UNLESS(saved.method == positions.method() || requested == InterpolationMethod::kAuto,
                     "orientation field: saved for " << to_string(saved.method)
                                                     << ", the positions use "
                                                     << to_string(positions.method()));
  VRREG_THROW_UNLESS(
      saved.mean_residual.allFinite() &&
          (saved.mean_residual.transpose() * saved.mean_residual - Eigen::Matrix3d::Identity())
                  .cwiseAbs()
                  .maxCoeff() < 1e-9,
      "orientation field: the mean residual is not a rotation");
  VRREG_THROW_UNLESS(std::isfinite(saved.joint_rms_rad) && saved.joint_rms_rad >= 0.0,
                     "orientation field: the joint model's sd must be finite and >= 0");
  VRREG_THROW_UNLESS(std::isfinite(saved.uncorrected_rms_rad) && saved.uncorrected_rms_rad >= 0.0 &&
                         std::isfinite(saved.cv_rms_rad) && saved.cv_rms_rad >= 0.0,
                     "orientation field: its cross-validated and uncorrected RMS angles must be "
                     "finite and >= 0");
  OrientationCorrector out;
  out.method_ = saved.method;
  out.applied_ = saved.applied;
  out.uncorrected_rms_rad_ = saved.uncorrected_rms_rad;
  out.cv_rms_rad_ = saved.cv_rms_rad;
  out.table_ = saved.cross_validation;
  out.T_robot_sensor_ = data.T_robot_sensor;
  out.mean_ = saved.mean_residual;
  if (saved.method == InterpolationMethod::kJoint) {
    VRREG_THROW_UNLESS(data.robot && data.has_joints(),
                       "orientation field: the joint model needs the robot and the joints");
    detail::validate_joint_rotation(saved.joint_terms, data.robot->n_joints());
    const bool positions_joint = positions.method() == InterpolationMethod::kJoint;
    VRREG_THROW_UNLESS(positions_joint ||
                           saved.joint_terms.position_rotation == PositionRotation::kNone,
                       "orientation field: the joint model's rotation needs the positions' joint "
                       "model");
    VRREG_THROW_UNLESS(positions_joint || saved.joint_terms.q_lo_rad.size() == data.robot->n_joints(),
                       "orientation field: the joint terms have no joint ranges");
    out.joint_model_ = true;
    if (positions_joint) out.joint_ = positions;
    out.joint_chain_ = data.robot;
    out.joint_terms_ = saved.joint_terms;
    out.joint_rms_rad_ = saved.joint_rms_rad;
    return out;
  }
  VRREG_THROW_UNLESS(saved.tangent, "orientation field: no saved tangent field");
  CorrectorData tangent =
      tangent_data(data, residual_rotations(residuals_robot_rad), out.mean_, noise_sd_rad);
  if (requested == InterpolationMethod::kAuto) {
    tangent.joints_rad.resize(0, 0);  // fitted as auto's Cartesian candidates are
    tangent.robot.reset();
  }
  out.tangent_ = Corrector::restore(*saved.tangent, tangent);
  return out;
}

SavedOrientationCorrector OrientationCorrector::save() const {
  SavedOrientationCorrector out;
  out.method = method_;
  out.applied = applied_;
  out.uncorrected_rms_rad = uncorrected_rms_rad_;
  out.cv_rms_rad = cv_rms_rad_;
  out.cross_validation = table_;
  out.mean_residual = mean_;
  out.joint_rms_rad = joint_rms_rad_;
  out.joint_terms = joint_terms_;
  if (tangent_) out.tangent = tangent_->save();
  return out;
}

bool OrientationCorrector::predicts_sd() const {
  return joint_model_ || (tangent_ && tangent_->sd_source() != SdSource::kNone);
}

std::string OrientationCorrector::describe() const {
  std::ostringstream out;
  if (joint_model_) {
    out << "joint model's rotation";
    if (joint_terms_.position_rotation == PositionRotation::kNone) {
      out << " (orientation terms only)";
    } else if (joint_terms_.position_rotation == PositionRotation::kJointAngles) {
      out << " (the positions' joint-angle errors and orientation terms)";
    } else if (joint_terms_.position_rotation == PositionRotation::kScaledJointAngles) {
      out << " (the positions' joint-angle errors, each scaled, and orientation terms)";
    }
    if (!joint_terms_.periodic.empty()) {
      out << ", " << joint_terms_.periodic.size() << " cyclic joint-angle error"
          << (joint_terms_.periodic.size() == 1 ? "" : "s");
    }
    if (joint_terms_.columns > 0) {
      out << ", " << joint_terms_.rank << " of " << joint_terms_.columns
          << " combinations identifiable";
    }
  } else {
    out << tangent_->describe();
  }
  out << ", about a mean rotation of " << 1e3 * rotation_log(mean_).norm() << " mrad";
  return out.str();
}

std::vector<StencilStatus> OrientationCorrector::joint_support(const CorrectionQuery& query) const {
  const JointRotationTerms& t = joint_terms_;
  std::vector<StencilStatus> out;
  for (Eigen::Index p = 0; p < query.joints_rad.cols(); ++p) {
    bool inside = true;
    for (Eigen::Index i = 0; i < query.joints_rad.rows(); ++i) {
      const double margin = kJointRangeMargin * (t.q_hi_rad(i) - t.q_lo_rad(i)) + kJointSlackRad;
      const double q = query.joints_rad(i, p);
      VRREG_THROW_UNLESS(std::isfinite(q), "orientation correction: a joint angle is not finite");
      inside = inside && q >= t.q_lo_rad(i) - margin && q <= t.q_hi_rad(i) + margin;
    }
    out.push_back(inside ? StencilStatus::kOk : StencilStatus::kOutsideSupport);
  }
  return out;
}

OrientationCorrection OrientationCorrector::correct(
    const CorrectionQuery& query, std::span<const Eigen::Matrix3d> R_sensor_marker,
    const TargetCorrection* positions_answer) const {
  const auto n = query.sensor_m.cols();
  VRREG_THROW_UNLESS(std::ssize(R_sensor_marker) == n,
                     "orientation correction: " << R_sensor_marker.size() << " orientations for "
                                                << n << " points");
  OrientationCorrection out;
  out.method_used = method_;
  out.sd_limit_rad = uncorrected_rms_rad_;
  out.corrections_robot_rad = Points3::Zero(3, n);
  const Eigen::Matrix3d& R = T_robot_sensor_.rotation;
  for (const Eigen::Matrix3d& r : R_sensor_marker) {
    VRREG_THROW_UNLESS(r.allFinite(), "orientation correction: an orientation is not finite");
    out.uncorrected_R_robot_marker.push_back(R * r);
  }
  out.corrected_R_robot_marker = out.uncorrected_R_robot_marker;
  // Where a correction holds (support, stencils): the positions' answer for the joint model
  // fitted with them, the joint terms' ranges for one without, the tangent field's own else.
  std::optional<TargetCorrection> own;
  if (joint_model_ && !joint_) {
    VRREG_THROW_UNLESS(query.joints_rad.cols() == n &&
                           query.joints_rad.rows() == joint_chain_->n_joints(),
                       "the orientation's joint model needs every point's "
                           << joint_chain_->n_joints() << " commanded joints");
    out.status = joint_support(query);
  } else {
    if (!joint_model_ || positions_answer == nullptr) {
      own = (joint_model_ ? *joint_ : *tangent_).correct(query);
    }
    const TargetCorrection& where = own ? *own : *positions_answer;
    VRREG_THROW_UNLESS(std::ssize(where.stencils) == n,
                       "orientation correction: the positions' answer has "
                           << where.stencils.size() << " points, not " << n);
    out.status.reserve(static_cast<std::size_t>(n));
    for (const Stencil& s : where.stencils) out.status.push_back(s.status);
  }
  if (!applied_) {  // not better than none: every point keeps its uncorrected orientation
    for (StencilStatus& s : out.status) {
      if (is_corrected(s)) s = StencilStatus::kNotBetterThanNone;
    }
  }
  // A stencil's tangent field has no sd inside its support, but one for the points it
  // extrapolated (far_field.hpp): then the answer carries them, NaN elsewhere.
  if (predicts_sd() || (own && own->predicted_sd_m.size() == n)) {
    out.predicted_sd_rad = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
  }
  for (Eigen::Index t = 0; t < n; ++t) {
    const auto k = static_cast<std::size_t>(t);
    if (!is_corrected(out.status[k])) {
      ++out.n_flagged;
      continue;
    }
    Eigen::Matrix3d D;
    if (joint_model_) {
      const auto q = query.joints_rad.col(t);
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      if (joint_terms_.position_rotation == PositionRotation::kFull ||
          joint_terms_.position_rotation == PositionRotation::kJointAngles) {
        e = *joint_->rotation_error_rad(
            q, joint_terms_.position_rotation == PositionRotation::kJointAngles);
      }
      std::optional<Eigen::VectorXd> dq;
      if (joint_terms_.position_rotation == PositionRotation::kScaledJointAngles) {
        dq = joint_->joint_angle_errors_rad(q);
      }
      D = rotation_exp(-e) *
          rotation_exp(-detail::joint_rotation_rad(joint_terms_, *joint_chain_, q,
                                                   dq ? &*dq : nullptr)) *
          mean_;
      out.predicted_sd_rad(t) = joint_rms_rad_;
    } else {
      D = rotation_exp(own->corrections_sensor_m.col(t)) * mean_;
      if (own->predicted_sd_m.size() == n) out.predicted_sd_rad(t) = own->predicted_sd_m(t);
    }
    out.corrections_robot_rad.col(t) = rotation_log(D);
    out.corrected_R_robot_marker[k] = D * out.uncorrected_R_robot_marker[k];
  }
  return out;
}

}  // namespace vrreg
