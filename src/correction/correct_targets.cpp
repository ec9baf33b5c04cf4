// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/correct_targets.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/correction/corrector.hpp"

namespace vrreg {
namespace {

void check_inputs(const CorrectionField& field, const ConstPoints3Ref& targets_sensor_m,
                  const ConstPoints3Ref& targets_robot_nominal_m,
                  const InterpolationSettings& settings) {
  const Eigen::Index n_fiducials = field.fiducials_robot_m.cols();
  VRREG_THROW_UNLESS(n_fiducials > 0, "the model has no fiducials to correct with");
  VRREG_THROW_UNLESS(field.corrections_sensor_m.cols() == n_fiducials,
                     "the model has " << field.corrections_sensor_m.cols()
                                      << " fiducial corrections for " << n_fiducials
                                      << " fiducials");
  VRREG_THROW_UNLESS(field.corrections_sensor_m.allFinite(),
                     "the model's fiducial corrections are not all finite");
  const SimilarityTransform& T = field.T_robot_sensor;
  VRREG_THROW_UNLESS(T.rotation.allFinite() && T.translation_m.allFinite() &&
                         std::isfinite(T.scale) && T.scale > 0.0,
                     "the model's transform is not finite (scale " << T.scale << ")");
  for (Eigen::Index j = 0; j < n_fiducials; ++j) {
    VRREG_THROW_UNLESS(field.fiducials_robot_m.col(j).allFinite(),
                       "fiducial " << j << " has no finite nominal robot position");
  }
  VRREG_THROW_UNLESS(field.fiducials_sequence.empty() ||
                         field.fiducials_sequence.size() == static_cast<std::size_t>(n_fiducials),
                     "got " << field.fiducials_sequence.size() << " sequence numbers for "
                            << n_fiducials << " fiducials");
  VRREG_THROW_UNLESS(targets_sensor_m.allFinite(),
                     "the targets' sensor coordinates are not all finite");
  VRREG_THROW_UNLESS(targets_robot_nominal_m.cols() == 0 ||
                         targets_robot_nominal_m.cols() == targets_sensor_m.cols(),
                     "got " << targets_robot_nominal_m.cols() << " nominal robot positions for "
                            << targets_sensor_m.cols() << " targets");
  VRREG_THROW_UNLESS(targets_robot_nominal_m.allFinite(),
                     "the targets' nominal robot coordinates are not all finite");
  VRREG_THROW_UNLESS(std::isfinite(settings.match_tolerance_m) && settings.match_tolerance_m > 0.0,
                     "the match tolerance must be > 0, got " << settings.match_tolerance_m << " m");
}

}  // namespace

TargetCorrection correct_targets(const CorrectionField& field,
                                 const ConstPoints3Ref& targets_sensor_m,
                                 const ConstPoints3Ref& targets_robot_nominal_m,
                                 const InterpolationSettings& settings,
                                 const std::vector<std::size_t>& targets_sequence) {
  check_inputs(field, targets_sensor_m, targets_robot_nominal_m, settings);
  CorrectorData data;
  data.T_robot_sensor = field.T_robot_sensor;
  data.fiducials_robot_m = field.fiducials_robot_m;
  data.corrections_sensor_m = field.corrections_sensor_m;
  data.sequence = field.fiducials_sequence;
  // The registered fiducials from Eq. 6: R X_j + tau = Y_j - s R epsilon_j.
  const SimilarityTransform& T = field.T_robot_sensor;
  data.registered_robot_m =
      field.fiducials_robot_m - T.scale * (T.rotation * field.corrections_sensor_m);
  CorrectorOptions options;
  options.interpolation = settings;
  // The paper's Eq. 7-8 as its experiments run them, one field per target set: unguarded, so
  // the tables are the method's own (the commands' correctors are guarded).
  options.guard = false;
  return Corrector::fit(data, options)
      .correct(CorrectionQuery(targets_sensor_m, targets_robot_nominal_m, Eigen::MatrixXd(0, 0),
                               targets_sequence));
}

}  // namespace vrreg
