// SPDX-License-Identifier: Apache-2.0
#include "procedure2_steps.hpp"

#include <string>

#include "orientation_rows.hpp"
#include "set_rows.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/pipeline/marker_offset.hpp"
#include "vrreg/planning/strategy3_registration.hpp"

namespace vrreg::pipeline_detail {

void require_configurations(const MeasurementSet& set, planning::Strategy strategy) {
  const std::string s = std::to_string(planning::strategy_number(strategy));
  if (!set.has_config) {
    fail(set, "`strategy` " + s + " needs a config column (the arm configuration of each row)");
  }
  if (set.n_joints == 0) {
    fail(set, "`strategy` " + s + " needs joint columns (q1_rad..qN_rad or q1_deg..qN_deg)");
  }
}

planning::Strategy2Result relabel(const MeasurementSet& set, kinematics::JointNorm norm,
                                  const std::optional<kinematics::SerialChain>& robot) {
  require_configurations(set, planning::Strategy::kAlongPath);
  try {
    return planning::relabel_strategy2(
        set, norm, robot ? kinematics::JointKinds(*robot) : kinematics::JointKinds());
  } catch (const FileError&) {
    throw;
  } catch (const InputError& e) {
    fail(set, e.what());
  }
}

void prepare_points(const RegistrationModel& model, const MeasurementSet& file_set,
                    planning::Strategy strategy, kinematics::JointNorm norm,
                    std::optional<int> config, bool robot_positions_required,
                    PointsToCorrect& out) {
  out.set = &file_set;
  if (model.T_registered_sensor) {  // the sensor moved since registration: back to its frame
    out.registered = file_set;
    for (Location& l : out.registered.locations) {
      l.sensor_m = model.T_registered_sensor->apply(l.sensor_m);
      if (l.q_sensor_marker) {
        l.q_sensor_marker = model.registered_sensor_orientation(*l.q_sensor_marker);
      }
    }
    out.set = &out.registered;
  }
  if (model.marker_offset) {
    out.moved = with_marker_offset(model, *out.set, Role::kTarget, robot_positions_required);
    out.set = &out.moved;
  }
  if (strategy == planning::Strategy::kAlongPath) {  // the points take the labels of their path
    planning::Strategy2Result r = relabel(*out.set, norm, model.robot);
    out.relabelled_set = std::move(r.set);
    out.relabelled = r.summary;
    out.set = &out.relabelled_set;
  }
  out.rows = select_rows(*out.set, Role::kTarget, config);
}

RegistrationModel volume_corner_model(const MeasurementSet& set, const planning::Procedure2& p2,
                                      const RegistrationOptions& registration,
                                      const InterpolationSettings& interpolation,
                                      RegistrationResult& registration_result,
                                      Points3& registered_sensor_m, Points3& registered_robot_m) {
  require_configurations(set, planning::Strategy::kVolumeCorners);
  RegistrationModel model;
  for (const std::size_t i : set.select(Role::kFiducial))
    model.fiducials.push_back(set.locations[i]);
  planning::Strategy3Options options;
  options.seed = p2.seed.value_or(1);
  options.match_tolerance_m = interpolation.match_tolerance_m;
  options.registration = registration;
  planning::Strategy3Registration r;
  try {
    r = planning::register_volume_corners(model.fiducials, options);
  } catch (const InputError& e) {
    fail(set, e.what());
  }
  registration_result = r.registration;
  registered_sensor_m.resize(3, 8);
  registered_robot_m.resize(3, 8);
  for (std::size_t c = 0; c < 8; ++c) {
    const Location& f = model.fiducials[r.corner_fiducials[c]];
    registered_sensor_m.col(static_cast<Eigen::Index>(c)) = f.sensor_m;
    registered_robot_m.col(static_cast<Eigen::Index>(c)) = f.robot_m;
    model.procedure2.registration_fiducials.push_back(r.corner_fiducials[c]);
  }
  model.T_robot_sensor = r.registration.T_robot_sensor;
  model.fre_m = r.registration.fre_m;
  model.corrections_sensor_m = r.corrections_sensor_m;
  model.interpolation = interpolation;
  model.source = set.source;
  model.procedure2.strategy = planning::Strategy::kVolumeCorners;
  model.procedure2.joint_norm = p2.joint_norm;
  model.procedure2.seed = options.seed;
  return model;
}

namespace {

// A cell of fewer fiducials than any method needs: every target keeps its uncorrected mapping
// (Eq. 2), flagged, and the layout says which method needs how many.
TargetCorrection uncorrected(const RegistrationModel& model, const MeasurementSet& set,
                             const std::vector<std::size_t>& rows, InterpolationMethod asked) {
  TargetCorrection out;
  out.method_used = asked == InterpolationMethod::kAuto ? InterpolationMethod::kLinear : asked;
  out.layout = "none: " + std::to_string(model.fiducials.size()) +
               " fiducials are fewer than any correction method needs (scattered and linear 4, "
               "grid, trilinear and octuplet 8, kriging, rbf and joint 12 or more); every "
               "target is left uncorrected";
  const Points3 sensor_m = set.sensor_points(rows);
  const auto n = static_cast<std::size_t>(sensor_m.cols());
  Stencil flagged;
  flagged.status = StencilStatus::kTooFewFiducials;
  out.stencils.assign(n, flagged);
  out.corrections_sensor_m = Points3::Zero(3, sensor_m.cols());
  out.corrected_sensor_m = sensor_m;
  out.uncorrected_robot_m = model.T_robot_sensor.apply_all(sensor_m);
  out.corrected_robot_m = out.uncorrected_robot_m;
  out.n_flagged = static_cast<int>(n);
  return out;
}

}  // namespace

TargetCorrection correct_rows(const RegistrationModel& model, const MeasurementSet& set,
                              const std::vector<std::size_t>& rows, const CorrectorRequest& request,
                              const Points3& nominal_robot_m,
                              std::optional<CrossValidation>* cross_validation,
                              std::optional<OrientationCorrection>* orientation) {
  const InterpolationSettings& settings = request.settings;
  if (request.strategy == planning::Strategy::kVolumeCorners) {
    require_configurations(set, planning::Strategy::kVolumeCorners);
    if (settings.method != InterpolationMethod::kOctuplet &&
        settings.method != InterpolationMethod::kLinear) {
      fail(set, std::string("`strategy` 3 corrects with octuplets, not `interpolation` ") +
                    to_string(settings.method));
    }
  }
  if (std::ssize(model.fiducials) < kMinCorrectableFiducials &&
      (request.strategy == planning::Strategy::kNone ||
       request.strategy == planning::Strategy::kAsListed)) {
    return uncorrected(model, set, rows, settings.method);
  }
  const bool field = is_field_model(settings.method);
  if (field && request.strategy == planning::Strategy::kAlongPath) {
    fail(set, std::string("`strategy` 2 corrects with the paper's stencils, not `interpolation` ") +
                  to_string(settings.method));
  }
  const auto correct = [&] {
    const Corrector corrector = corrector_for(model, request);
    if (cross_validation != nullptr && settings.method == InterpolationMethod::kAuto) {
      *cross_validation = corrector.cross_validation();
    }
    const Eigen::MatrixXd joints =
        corrector.needs().joints ? joints_of(set, rows) : Eigen::MatrixXd(0, 0);
    const std::vector<std::size_t> lines = source_lines(set, rows);
    const Points3 sensor_m = set.sensor_points(rows);  // the query is a view: kept alive here
    // A lost-motion term reads each target's approach directions (none known: both covered).
    const bool lost_motion = corrector.lost_motion() && corrector.lost_motion()->applied;
    const Eigen::MatrixXd approach = lost_motion ? approach_of(set, rows) : Eigen::MatrixXd(0, 0);
    CorrectionQuery query(sensor_m, nominal_robot_m, joints, lines, approach);
    query.extrapolate = request.extrapolate;
    TargetCorrection positions = corrector.correct(query);
    if (orientation != nullptr) {
      // The orientations' joint model needs the joints even where the positions' method does not.
      const Eigen::MatrixXd orientation_joints =
          !corrector.needs().joints && set.n_joints > 0 ? joints_of(set, rows) : Eigen::MatrixXd(0, 0);
      CorrectionQuery orientation_query(sensor_m, nominal_robot_m,
                                        corrector.needs().joints ? joints : orientation_joints,
                                        lines);
      orientation_query.extrapolate = request.extrapolate;
      *orientation = correct_orientation_rows(model, set, rows, corrector, orientation_query,
                                              positions, request.robot);
    }
    return positions;
  };
  // The field models and Strategy 3 need more of the targets' file (joints, configurations):
  // their errors name it.
  if (!field && request.strategy != planning::Strategy::kVolumeCorners) return correct();
  try {
    return correct();
  } catch (const FileError&) {
    throw;
  } catch (const InputError& e) {
    fail(set, e.what());
  }
}

}  // namespace vrreg::pipeline_detail
