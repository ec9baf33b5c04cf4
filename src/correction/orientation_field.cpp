// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/orientation_field.hpp"

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
  return tangent;
}

}  // namespace

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

OrientationCorrector OrientationCorrector::fit(const Corrector& positions,
                                               const CorrectorData& data,
                                               const ConstPoints3Ref& residuals_robot_rad,
                                               std::optional<double> noise_sd_rad) {
  check_inputs(data, residuals_robot_rad, noise_sd_rad);
  OrientationCorrector out;
  out.method_ = positions.method();
  out.T_robot_sensor_ = data.T_robot_sensor;
  std::vector<Eigen::Matrix3d> rotations = residual_rotations(residuals_robot_rad);
  if (out.method_ == InterpolationMethod::kJoint) {
    // The arm's orientation error as the fitted joint model predicts it, e(q), and what only
    // orientations show, g(q): the residual D_j = exp(-(e + g)(q_j)) C, C the registration's
    // rotation error (and the marker's misalignment), all to the first order.
    VRREG_THROW_UNLESS(data.has_joints() && data.robot,
                       "orientation field: the joint model needs joints and the robot");
    out.joint_ = positions;
    out.joint_chain_ = data.robot;
    const auto n = static_cast<std::size_t>(data.size());
    std::vector<Eigen::Vector3d> e(n);
    std::vector<Eigen::Matrix3d> left(n);
    for (std::size_t j = 0; j < n; ++j) {
      const std::optional<Eigen::Vector3d> e_j =
          positions.rotation_error_rad(data.joints_rad.col(static_cast<Eigen::Index>(j)));
      VRREG_THROW_UNLESS(e_j, "orientation field: the joint model predicts no rotation");
      e[j] = *e_j;
      left[j] = rotation_exp(e[j]) * rotations[j];
    }
    const Eigen::Matrix3d C0 = rotation_mean(left);
    Points3 g(3, data.size());
    for (std::size_t j = 0; j < n; ++j) {
      g.col(static_cast<Eigen::Index>(j)) = -rotation_log(left[j] * C0.transpose());
    }
    out.joint_terms_ = detail::fit_joint_rotation(*data.robot, data.joints_rad, g);
    std::vector<Eigen::Matrix3d> model(n);
    for (std::size_t j = 0; j < n; ++j) {
      const auto col = static_cast<Eigen::Index>(j);
      model[j] = rotation_exp(-(e[j] + detail::joint_rotation_rad(out.joint_terms_, *data.robot,
                                                                  data.joints_rad.col(col))));
      left[j] = model[j].transpose() * rotations[j];
    }
    out.mean_ = rotation_mean(left);
    double sum_sq = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      sum_sq += std::pow(rotation_angle_rad(model[j] * out.mean_, rotations[j]), 2);
    }
    out.joint_rms_rad_ = std::sqrt(sum_sq / static_cast<double>(n));
    return out;
  }
  out.mean_ = rotation_mean(rotations);
  const CorrectorData tangent = tangent_data(data, rotations, out.mean_, noise_sd_rad);
  CorrectorOptions options;
  options.interpolation = positions.requested();
  options.interpolation.method = out.method_;  // auto: the positions' choice
  options.nearest_configuration = positions.nearest_configuration();
  options.tabulate = positions.tabulated();
  out.tangent_ = Corrector::fit(tangent, options);
  return out;
}

OrientationCorrector OrientationCorrector::restore(const SavedOrientationCorrector& saved,
                                                   const Corrector& positions,
                                                   const CorrectorData& data,
                                                   const ConstPoints3Ref& residuals_robot_rad,
                                                   std::optional<double> noise_sd_rad) {
  check_inputs(data, residuals_robot_rad, noise_sd_rad);
  VRREG_THROW_UNLESS(saved.method == positions.method(), "orientation field: saved for "
                                                             << to_string(saved.method)
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
  OrientationCorrector out;
  out.method_ = saved.method;
  out.T_robot_sensor_ = data.T_robot_sensor;
  out.mean_ = saved.mean_residual;
  if (saved.method == InterpolationMethod::kJoint) {
    VRREG_THROW_UNLESS(data.robot, "orientation field: the joint model needs the robot");
    detail::validate_joint_rotation(saved.joint_terms, data.robot->n_joints());
    out.joint_ = positions;
    out.joint_chain_ = data.robot;
    out.joint_terms_ = saved.joint_terms;
    out.joint_rms_rad_ = saved.joint_rms_rad;
    return out;
  }
  VRREG_THROW_UNLESS(saved.tangent, "orientation field: no saved tangent field");
  out.tangent_ = Corrector::restore(
      *saved.tangent,
      tangent_data(data, residual_rotations(residuals_robot_rad), out.mean_, noise_sd_rad));
  return out;
}

SavedOrientationCorrector OrientationCorrector::save() const {
  SavedOrientationCorrector out;
  out.method = method_;
  out.mean_residual = mean_;
  out.joint_rms_rad = joint_rms_rad_;
  out.joint_terms = joint_terms_;
  if (tangent_) out.tangent = tangent_->save();
  return out;
}

bool OrientationCorrector::predicts_sd() const {
  return joint_.has_value() || (tangent_ && tangent_->sd_source() != SdSource::kNone);
}

std::string OrientationCorrector::describe() const {
  std::ostringstream out;
  out << (joint_ ? "joint model's rotation" : tangent_->describe()) << ", about a mean rotation of "
      << 1e3 * rotation_log(mean_).norm() << " mrad";
  return out.str();
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
  out.corrections_robot_rad = Points3::Zero(3, n);
  const Eigen::Matrix3d& R = T_robot_sensor_.rotation;
  for (const Eigen::Matrix3d& r : R_sensor_marker) {
    VRREG_THROW_UNLESS(r.allFinite(), "orientation correction: an orientation is not finite");
    out.uncorrected_R_robot_marker.push_back(R * r);
  }
  out.corrected_R_robot_marker = out.uncorrected_R_robot_marker;
  // The positions' answer says where a correction holds (support, stencils): the same points.
  std::optional<TargetCorrection> own;
  if (!joint_ || positions_answer == nullptr) own = (joint_ ? *joint_ : *tangent_).correct(query);
  const TargetCorrection& where = own ? *own : *positions_answer;
  VRREG_THROW_UNLESS(std::ssize(where.stencils) == n,
                     "orientation correction: the positions' answer has " << where.stencils.size()
                                                                          << " points, not " << n);
  out.status.reserve(static_cast<std::size_t>(n));
  for (const Stencil& s : where.stencils) out.status.push_back(s.status);
  if (predicts_sd()) {
    out.predicted_sd_rad = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
  }
  for (Eigen::Index t = 0; t < n; ++t) {
    const auto k = static_cast<std::size_t>(t);
    if (!is_corrected(out.status[k])) {
      ++out.n_flagged;
      continue;
    }
    Eigen::Matrix3d D;
    if (joint_) {
      const auto q = query.joints_rad.col(t);
      const std::optional<Eigen::Vector3d> e = joint_->rotation_error_rad(q);
      D = rotation_exp(-(*e + detail::joint_rotation_rad(joint_terms_, *joint_chain_, q))) * mean_;
      out.predicted_sd_rad(t) = joint_rms_rad_;
    } else {
      D = rotation_exp(where.corrections_sensor_m.col(t)) * mean_;
      if (where.predicted_sd_m.size() == n) out.predicted_sd_rad(t) = where.predicted_sd_m(t);
    }
    out.corrections_robot_rad.col(t) = rotation_log(D);
    out.corrected_R_robot_marker[k] = D * out.uncorrected_R_robot_marker[k];
  }
  return out;
}

}  // namespace vrreg
