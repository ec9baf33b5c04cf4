// SPDX-License-Identifier: Apache-2.0
#include "vrreg/pipeline/correct.hpp"

#include "model_corrector.hpp"
#include "orientation_rows.hpp"
#include "procedure2_steps.hpp"
#include "set_rows.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/pipeline/prepared_corrector.hpp"

namespace vrreg {
namespace {

using planning::Strategy;

CorrectResult correct_set(const RegistrationModel& model, const MeasurementSet& file_set,
                          const CorrectOptions& options) {
  model.validate();
  const Strategy strategy = model.procedure2.strategy;  // Procedure 2 (section 4.4): as registered
  const kinematics::JointNorm norm = model.procedure2.joint_norm;
  pipeline_detail::PointsToCorrect points;
  pipeline_detail::prepare_points(model, file_set, strategy, norm,
                                  options.config ? options.config : model.config, false, points);
  const MeasurementSet* set = points.set;
  const std::vector<std::size_t>& rows = points.rows;
  CorrectResult out;
  out.interpolation = options.interpolation.apply(model.interpolation);
  Points3 nominal(3, 0);
  if (out.interpolation.method == InterpolationMethod::kOctuplet ||
      strategy == Strategy::kVolumeCorners) {
    for (const std::size_t i : rows) {
      if (!set->locations[i].has_robot) {
        pipeline_detail::fail(*set,
                              "octuplet interpolation needs the nominal robot position of every "
                              "point (robot_x_mm, ...)",
                              set->locations[i].source_line);
      }
    }
    nominal = set->robot_points(rows);
  }
  const pipeline_detail::CorrectorRequest request{out.interpolation, strategy, norm, options.robot,
                                                  options.refit, options.exact,
                                                  options.extrapolate};
  out.correction = pipeline_detail::correct_rows(model, *set, rows, request, nominal,
                                                 &out.cross_validation, &out.orientation);
  pipeline_detail::labels_of(*set, rows, out.names, out.configs);
  return out;
}


bool corrects_point_by_point(const RegistrationModel& model, const CorrectOptions& options) {
  // Too few fiducials: the set's way flags every point, naming the minimum.
  return std::ssize(model.fiducials) >= kMinCorrectableFiducials &&
         model.procedure2.strategy != Strategy::kAlongPath &&
         model.procedure2.strategy != Strategy::kVolumeCorners && !options.config &&
         !model.config && !model.marker_offset;
}

pipeline_detail::CorrectorRequest corrector_request(const RegistrationModel& model,
                                                    const CorrectOptions& options) {
  return {options.interpolation.apply(model.interpolation), model.procedure2.strategy,
          model.procedure2.joint_norm, options.robot, options.refit, options.exact,
          options.extrapolate};
}

// Every point, straight from the caller's arrays: no per-point records (10^6 points stay 10^6
// columns), the same numbers as the set's way.
CorrectResult correct_points(const Corrector& corrector, const OrientationCorrector* orientation,
                             const MeasuredPoints& points,
                             const InterpolationSettings& interpolation, bool extrapolate) {
  points.validate(false);
  CorrectResult out;
  out.interpolation = interpolation;
  if (out.interpolation.method == InterpolationMethod::kAuto) {
    out.cross_validation = corrector.cross_validation();
  }
  const MethodNeeds needs = corrector.needs();
  VRREG_THROW_UNLESS(!needs.nominal_robot || points.robot_m.cols() == points.size(),
                     to_string(corrector.method())
                         << " interpolation needs the nominal robot position of every point "
                            "(robot_m)");
  VRREG_THROW_UNLESS(!needs.joints || points.joints_rad.cols() == points.size(),
                     to_string(corrector.method())
                         << " interpolation needs the joint angles of every point (joints_rad)");
  // Points given in memory were read at no file line: sequence 0, as the set's way has it.
  const std::vector<std::size_t> sequence(
      needs.nominal_robot ? static_cast<std::size_t>(points.size()) : 0, 0);
  const Points3 no_points(3, 0);
  const Eigen::MatrixXd no_joints(0, 0);
  const bool lost_motion = corrector.lost_motion() && corrector.lost_motion()->applied &&
                           points.approach_sign.cols() == points.size();
  CorrectionQuery query(points.sensor_m, needs.nominal_robot ? points.robot_m : no_points,
                        needs.joints ? points.joints_rad : no_joints, sequence,
                        lost_motion ? points.approach_sign : no_joints);
  query.extrapolate = extrapolate;
  out.correction = corrector.correct(query);
  if (!points.q_sensor_marker.empty()) {
    VRREG_THROW_UNLESS(orientation != nullptr, "no orientation field for the points' orientations");
    std::vector<Eigen::Matrix3d> R_sensor_marker;
    R_sensor_marker.reserve(points.q_sensor_marker.size());
    for (const Eigen::Quaterniond& q : points.q_sensor_marker) {
      R_sensor_marker.push_back(unit_quaternion(q.coeffs(), "q_sensor_marker").toRotationMatrix());
    }
    // The orientations' joint model needs the joints even where the positions' method does not.
    CorrectionQuery orientation_query(
        points.sensor_m, needs.nominal_robot ? points.robot_m : no_points,
        points.joints_rad.cols() == points.size() ? points.joints_rad : no_joints, sequence);
    orientation_query.extrapolate = extrapolate;
    out.orientation = orientation->correct(orientation_query, R_sensor_marker, &out.correction);
  }
  out.names = points.names;
  for (const int config : points.configs) out.configs.emplace_back(config);
  return out;
}

// The points as the model's corrector takes them: after a bump, in the registration's sensor frame.
MeasuredPoints in_registered_frame(const RegistrationModel& model, const MeasuredPoints& points) {
  if (!model.T_registered_sensor) return points;
  MeasuredPoints out = points;
  out.sensor_m = model.registered_sensor_points(points.sensor_m);
  for (Eigen::Quaterniond& q : out.q_sensor_marker) q = model.registered_sensor_orientation(q);
  return out;
}

// Labels and joints decide which points and which fiducials: the set's way.
CorrectResult correct_as_set(const RegistrationModel& model, const MeasuredPoints& points,
                             const CorrectOptions& options) {
  CorrectResult out = correct_set(model, points.to_measurement_set(Role::kTarget, false), options);
  if (points.names.empty()) out.names.clear();
  return out;
}

}  // namespace

CorrectResult correct(const RegistrationModel& model, const MeasurementSet& points,
                      const CorrectOptions& options) {
  return correct_set(model, points, options);
}

CorrectResult correct(const RegistrationModel& model, const MeasuredPoints& points,
                      const CorrectOptions& options) {
  pipeline_detail::require_orientation_field(model, points.q_sensor_marker.size());
  if (!corrects_point_by_point(model, options)) return correct_as_set(model, points, options);
  model.validate();
  const pipeline_detail::CorrectorRequest request = corrector_request(model, options);
  const Corrector corrector = pipeline_detail::corrector_for(model, request);
  std::optional<OrientationCorrector> orientation;
  if (!points.q_sensor_marker.empty()) {
    orientation = pipeline_detail::orientation_field_for(model, corrector, request.robot);
  }
  return correct_points(corrector, orientation ? &*orientation : nullptr,
                        in_registered_frame(model, points), request.settings, options.extrapolate);
}

PreparedCorrector::PreparedCorrector(std::shared_ptr<const RegistrationModel> model,
                                     CorrectOptions options)
    : model_(std::move(model)), options_(std::move(options)) {
  VRREG_THROW_UNLESS(model_ != nullptr, "no model given");
  model_->validate();
  const pipeline_detail::CorrectorRequest request = corrector_request(*model_, options_);
  const Corrector corrector = pipeline_detail::corrector_for(*model_, request);
  method_ = corrector.method();
  predicts_sd_ = corrector.sd_source() != SdSource::kNone;
  if (corrector.needs().joints) {
    // The fiducials' joints: every point is compared with them.
    joints_needed_ = static_cast<int>(model_->fiducials.front().q_rad.size());
  }
  corrects_orientation_ = model_->has_fiducial_orientations();
  if (corrects_point_by_point(*model_, options_)) {
    corrector_ = std::make_shared<const Corrector>(corrector);
    if (corrects_orientation_) {
      orientation_ = std::make_shared<const OrientationCorrector>(
          *pipeline_detail::orientation_field_for(*model_, corrector, request.robot));
      predicts_angle_sd_ = orientation_->predicts_sd();
    }
  } else if (corrects_orientation_) {
    predicts_angle_sd_ =
        pipeline_detail::orientation_field_for(*model_, corrector, request.robot)->predicts_sd();
  }
}

CorrectResult PreparedCorrector::correct(const MeasuredPoints& points) const {
  return correct(points, options_.extrapolate);
}

CorrectResult PreparedCorrector::correct(const MeasuredPoints& points, bool extrapolate) const {
  pipeline_detail::require_orientation_field(*model_, points.q_sensor_marker.size());
  if (!corrector_) {
    CorrectOptions options = options_;
    options.extrapolate = extrapolate;
    return correct_as_set(*model_, points, options);
  }
  return correct_points(*corrector_, orientation_.get(), in_registered_frame(*model_, points),
                        options_.interpolation.apply(model_->interpolation), extrapolate);
}

InterpolationMethod PreparedCorrector::method() const { return method_; }
int PreparedCorrector::joints_needed() const { return joints_needed_; }
bool PreparedCorrector::predicts_sd() const { return predicts_sd_; }
bool PreparedCorrector::corrects_orientation() const { return corrects_orientation_; }
bool PreparedCorrector::predicts_angle_sd() const { return predicts_angle_sd_; }

}  // namespace vrreg
