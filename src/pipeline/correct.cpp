#include "vrreg/pipeline/correct.hpp"

#include "procedure2_steps.hpp"
#include "set_rows.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/pipeline/marker_offset.hpp"

namespace vrreg {
namespace {

using planning::Strategy;

CorrectResult correct_set(const RegistrationModel& model, const MeasurementSet& file_set,
                          const CorrectOptions& options) {
  model.validate();
  // Hand-eye model: points with joints get their robot positions from the estimated offset.
  MeasurementSet moved;
  if (model.marker_offset) moved = with_marker_offset(model, file_set, Role::kTarget, false);
  const MeasurementSet& input = model.marker_offset ? moved : file_set;
  const Strategy strategy = model.procedure2.strategy;  // Procedure 2 (section 4.4): as registered
  const kinematics::JointNorm norm = model.procedure2.joint_norm;
  const MeasurementSet* set = &input;
  MeasurementSet relabelled;
  if (strategy == Strategy::kAlongPath) {
    relabelled = pipeline_detail::relabel(input, norm).set;
    set = &relabelled;
  }
  const std::optional<int> config = options.config ? options.config : model.config;
  const std::vector<std::size_t> rows = pipeline_detail::select_rows(*set, Role::kTarget, config);
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
  out.correction = pipeline_detail::correct_rows(model, *set, rows, out.interpolation, strategy,
                                                 norm, nominal,
                                                 options.robot ? options.robot : model.robot,
                                                 &out.cross_validation);
  pipeline_detail::labels_of(*set, rows, out.names, out.configs);
  return out;
}

}  // namespace

CorrectResult correct(const RegistrationModel& model, const MeasurementSet& points,
                      const CorrectOptions& options) {
  return correct_set(model, points, options);
}

CorrectResult correct(const RegistrationModel& model, const MeasuredPoints& points,
                      const CorrectOptions& options) {
  const bool per_point = !is_field_model(options.interpolation.apply(model.interpolation).method) &&
                         model.procedure2.strategy != Strategy::kAlongPath &&
                         model.procedure2.strategy != Strategy::kVolumeCorners &&
                         !options.config && !model.config && !model.marker_offset;
  if (!per_point) {  // labels and joints decide which points and which fiducials: the set's way
    CorrectResult out = correct_set(model, points.to_measurement_set(Role::kTarget, false), options);
    if (points.names.empty()) out.names.clear();
    return out;
  }
  // Every point, straight from the caller's arrays: no per-point records (10^6 points stay 10^6
  // columns), the same numbers as the set's way.
  model.validate();
  points.validate(false);
  CorrectResult out;
  out.interpolation = options.interpolation.apply(model.interpolation);
  const bool octuplet = out.interpolation.method == InterpolationMethod::kOctuplet;
  VRREG_THROW_UNLESS(!octuplet || points.robot_m.cols() == points.size(),
                     "octuplet interpolation needs the nominal robot position of every point "
                     "(robot_m)");
  // Points given in memory were read at no file line: sequence 0, as the set's way has it.
  const std::vector<std::size_t> sequence(octuplet ? static_cast<std::size_t>(points.size()) : 0, 0);
  out.correction = correct_targets(model.correction_field(), points.sensor_m,
                                   octuplet ? points.robot_m : Points3(3, 0), out.interpolation,
                                   sequence);
  out.names = points.names;
  for (const int config : points.configs) out.configs.emplace_back(config);
  return out;
}

}  // namespace vrreg
