// SPDX-License-Identifier: Apache-2.0
#include "orientation_rows.hpp"

#include <cmath>

#include "model_corrector.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/metrics/noise.hpp"

namespace vrreg::pipeline_detail {

OrientationInputs orientation_inputs(const RegistrationModel& model) {
  std::vector<Eigen::Matrix3d> measured, commanded;
  for (const Location& f : model.fiducials) {
    measured.push_back(f.q_sensor_marker.value().toRotationMatrix());
    commanded.push_back(f.q_robot_marker.value().toRotationMatrix());
  }
  OrientationInputs out{rotation_residuals_rad(model.T_robot_sensor.rotation, measured, commanded),
                        sigma_opt_rad(model.fiducials)};
  // The noise of one fiducial's averaged orientation per axis: sigma_opt over sqrt(readings).
  if (out.noise_sd_rad) *out.noise_sd_rad /= std::sqrt(median_readings(model.fiducials));
  return out;
}

OrientationCorrector fit_orientation(const RegistrationModel& model, const Corrector& positions,
                                     const std::optional<kinematics::SerialChain>& robot) {
  const OrientationInputs in = orientation_inputs(model);
  return OrientationCorrector::fit(positions, corrector_data(model, robot ? robot : model.robot),
                                   in.residuals_rad, in.noise_sd_rad);
}

std::optional<OrientationCorrector> orientation_field_for(
    const RegistrationModel& model, const Corrector& positions,
    const std::optional<kinematics::SerialChain>& robot) {
  if (!model.has_fiducial_orientations()) return std::nullopt;
  if (model.orientation_corrector && model.corrector &&
      positions.shares_fit_with(*model.corrector)) {
    return model.orientation_corrector;
  }
  return fit_orientation(model, positions, robot);
}

void require_orientation_field(const RegistrationModel& model, std::size_t n_orientations) {
  VRREG_THROW_UNLESS(n_orientations == 0 || model.has_fiducial_orientations(),
                     "the points carry orientations but the model's fiducials do not (register "
                     "rigid-body fiducials with measured and commanded orientations to correct "
                     "orientations; docs/orientation.md)");
}

std::optional<OrientationCorrection> correct_orientation_rows(
    const RegistrationModel& model, const MeasurementSet& set, const std::vector<std::size_t>& rows,
    const Corrector& positions, const CorrectionQuery& query, const TargetCorrection& answer,
    const std::optional<kinematics::SerialChain>& robot) {
  if (!model.has_fiducial_orientations()) return std::nullopt;
  std::vector<Eigen::Matrix3d> R_sensor_marker;
  for (const std::size_t r : rows) {
    const Location& l = set.locations.at(r);
    if (!l.q_sensor_marker) return std::nullopt;
    R_sensor_marker.push_back(l.q_sensor_marker->toRotationMatrix());
  }
  return orientation_field_for(model, positions, robot)->correct(query, R_sensor_marker, &answer);
}

}  // namespace vrreg::pipeline_detail

namespace vrreg {

OrientationCorrector restore_orientation_corrector(const RegistrationModel& model,
                                                   const SavedOrientationCorrector& saved) {
  VRREG_THROW_UNLESS(model.corrector, "an orientation field needs the model's corrector");
  VRREG_THROW_UNLESS(model.has_fiducial_orientations(),
                     "an orientation field needs every fiducial's measured and commanded "
                     "orientation");
  const pipeline_detail::OrientationInputs in = pipeline_detail::orientation_inputs(model);
  return OrientationCorrector::restore(saved, *model.corrector,
                                       pipeline_detail::corrector_data(model, model.robot),
                                       in.residuals_rad, in.noise_sd_rad);
}

}  // namespace vrreg
