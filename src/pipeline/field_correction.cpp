#include "field_correction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cross_validation.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/correction/local_rms.hpp"
#include "vrreg/metrics/noise.hpp"

namespace vrreg::pipeline_detail {
namespace {

constexpr int kLocalCvNeighbours = 16;

// Whether a target's sigma_pred is the RMS of its nearest fiducials' held-out errors (else one
// global CV RMS). The errors vary over the volume, and one global RMS was pessimistic for the
// targets (simulated A1, trilinear: RMS of TRE/sd 0.80 with one global CV RMS, 0.84 local). Not
// for the joint model: its held-out errors depend on which joint angles the training fiducials
// share with the held-out one, not on where it is, and near a target they can be much smaller
// than at it (27-fiducial cube, 10 seeds: RMS of TRE/sd 0.43 global, 2.95 local).
bool sd_is_local(InterpolationMethod method) { return method != InterpolationMethod::kJoint; }

}  // namespace

FieldData field_data(const RegistrationModel& model,
                     const std::optional<kinematics::SerialChain>& robot) {
  FieldData data;
  const CorrectionField field = model.correction_field();
  data.T_robot_sensor = model.T_robot_sensor;
  data.fiducials_robot_m = field.fiducials_robot_m;
  data.corrections_sensor_m = field.corrections_sensor_m;
  data.tolerance_m = model.interpolation.match_tolerance_m;
  const auto n = static_cast<Eigen::Index>(model.fiducials.size());
  data.registered_robot_m.resize(3, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    data.registered_robot_m.col(j) =
        model.T_robot_sensor.apply(model.fiducials[static_cast<std::size_t>(j)].sensor_m);
  }
  const std::size_t n_joints = model.fiducials.front().q_rad.size();
  bool joints = n_joints > 0;
  for (const Location& f : model.fiducials) joints = joints && f.q_rad.size() == n_joints;
  if (joints) {
    data.joints_rad.resize(static_cast<Eigen::Index>(n_joints), n);
    for (Eigen::Index j = 0; j < n; ++j) {
      const std::vector<double>& q = model.fiducials[static_cast<std::size_t>(j)].q_rad;
      data.joints_rad.col(j) = Eigen::Map<const Eigen::VectorXd>(q.data(), q.size());
    }
  }
  data.robot = robot;
  // The measured part of one fiducial's noise per axis: its averaged sensor reading, sigma_opt
  // per reading over sqrt n. The robot's repeatability is left to the fit (kriging's nugget
  // excess): a datasheet's sigma_rep is a bound, often 2-3 sigma, and as a floor it over-smooths
  // (simulated A1: 0.141 mm and sd 1.3x too wide with the 0.1 mm spec; 0.127 mm, calibrated,
  // without it).
  const std::optional<double> opt = sigma_opt_m(model.fiducials);
  if (opt) {
    std::vector<int> readings;
    for (const Location& f : model.fiducials) readings.push_back(std::max(f.n_readings, 1));
    std::nth_element(readings.begin(), readings.begin() + readings.size() / 2, readings.end());
    data.noise_sd_m = *opt / std::sqrt(static_cast<double>(readings[readings.size() / 2]));
  }
  return data;
}

FittedField fit_field(InterpolationMethod method, const FieldData& data) {
  FittedField out;
  const int folds = 5;
  const std::uint64_t seed = 1;
  if (method == InterpolationMethod::kAuto) {
    out.cross_validation = choose_by_cross_validation(data, folds, seed, &out.model);
    out.method = out.cross_validation->chosen;
    for (const CrossValidationRow& row : out.cross_validation->rows) {
      if (row.method == out.method) {
        out.cv_rms_m = row.rms_m;
        if (sd_is_local(out.method)) out.cv_squared_error_m2 = row.squared_error_m2;
      }
    }
    return out;
  }
  VRREG_THROW_UNLESS(is_field_model(method), to_string(method) << " is not a field model");
  out.method = method;
  if (method == InterpolationMethod::kKriging) {  // its own posterior sd: no CV needed
    out.model = fit_field_model(method, data);
    return out;
  }
  // The model's own uncertainty is its cross-validated error.
  const CrossValidationRow row =
      cross_validate(method, data, assign_folds(data.size(), folds, seed), folds, &out.model);
  VRREG_THROW_UNLESS(row.applicable && out.model,
                     to_string(method) << " interpolation cannot be used on these fiducials: "
                                       << row.note);
  out.cv_rms_m = row.rms_m;
  if (sd_is_local(method)) out.cv_squared_error_m2 = row.squared_error_m2;
  return out;
}

TargetCorrection correct_with_field(const FittedField& field, const FieldData& data,
                                    const ConstPoints3Ref& targets_sensor_m,
                                    const Eigen::MatrixXd& targets_joints_rad) {
  VRREG_THROW_UNLESS(targets_sensor_m.allFinite(),
                     "the targets' sensor coordinates are not all finite");
  const Eigen::Index n = targets_sensor_m.cols();
  const SimilarityTransform& T = data.T_robot_sensor;
  TargetCorrection out;
  out.method_used = field.method;
  out.layout = field.model->describe();
  out.uncorrected_robot_m.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i)
    out.uncorrected_robot_m.col(i) = T.apply(Eigen::Vector3d(targets_sensor_m.col(i)));
  if (field.method == InterpolationMethod::kJoint) {
    VRREG_THROW_UNLESS(targets_joints_rad.cols() == n && data.robot &&
                           targets_joints_rad.rows() == data.robot->n_joints(),
                       "joint interpolation needs every target's joint angles");
  }
  const FieldPredictions p = field.model->predict(FieldQuery{out.uncorrected_robot_m,
                                                             targets_joints_rad});
  out.stencils.resize(static_cast<std::size_t>(n));
  out.corrections_sensor_m = p.corrections_sensor_m;
  out.corrected_sensor_m.resize(3, n);
  out.corrected_robot_m.resize(3, n);
  out.predicted_sd_m.resize(n);
  // Per-fiducial held-out errors (a position model, see FittedField): those of the target's 16
  // nearest fiducials (48 squared components, the RMS to about +-10 %).
  Eigen::VectorXd local_sd_m;
  if (p.sd_m.size() != n && field.cv_squared_error_m2.size() == data.size()) {
    local_sd_m = local_rms(data.registered_robot_m, field.cv_squared_error_m2,
                           out.uncorrected_robot_m, kLocalCvNeighbours);
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (p.ok[k] == 0) {
      out.stencils[k].status = StencilStatus::kOutsideGrid;
      out.corrections_sensor_m.col(i).setZero();
      out.corrected_sensor_m.col(i) = targets_sensor_m.col(i);
      out.corrected_robot_m.col(i) = out.uncorrected_robot_m.col(i);
      out.predicted_sd_m(i) = std::numeric_limits<double>::quiet_NaN();
      ++out.n_flagged;
      continue;
    }
    const Eigen::Vector3d corrected = targets_sensor_m.col(i) + p.corrections_sensor_m.col(i);
    out.corrected_sensor_m.col(i) = corrected;  // Eq. 8
    out.corrected_robot_m.col(i) = T.apply(corrected);
    // The error of a corrected target is the field's error plus the target's own noise; the
    // cross-validated errors hold both (a held-out fiducial is noisy too), kriging gives them
    // apart.
    out.predicted_sd_m(i) = p.sd_m.size() == n         ? p.sd_m(i)
                            : local_sd_m.size() == n ? local_sd_m(i)
                                                     : field.cv_rms_m;
  }
  return out;
}

}  // namespace vrreg::pipeline_detail
