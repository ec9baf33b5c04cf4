// SPDX-License-Identifier: Apache-2.0
#include "robust_rows.hpp"

#include <limits>

#include "set_rows.hpp"
#include "vrreg/correction/rrbc.hpp"
#include "vrreg/metrics/noise.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg::pipeline_detail {

RobustRows robust_rows(const MeasurementSet& set, const std::vector<std::size_t>& rows,
                       const RegisterOptions& options) {
  const Points3 sensor = set.sensor_points(rows);
  const Points3 robot = set.robot_points(rows);
  // Any registration will do: the LOO deviations do not depend on it (outliers.hpp, step 1).
  const RegistrationResult first = register_rigid(sensor, robot, options.registration);
  const Points3 eps = fiducial_corrections(first.T_robot_sensor, sensor, robot);  // Eq. 6
  std::vector<int> groups;
  for (const std::size_t row : rows) {
    groups.push_back(set.locations[row].config.value_or(std::numeric_limits<int>::min()));
  }
  const NoiseFigures noise =
      noise_figures(sigma_opt_m(locations_of(set, rows)), options.sigma_rep_m, 0.0);  // Eq. 9
  RobustRows out;
  out.report.detection = detect_outlier_fiducials(robot, eps, groups, noise.sigma_noise_m,
                                                  *options.robust);
  out.report.false_alarm_rate = options.robust->false_alarm_rate;
  const OutlierDetection& d = out.report.detection;
  if (!d.converged) fail(set, "robust check failed: " + d.message);
  std::size_t next = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (next < d.outliers.size() && d.outliers[next].fiducial == static_cast<Eigen::Index>(k)) {
      const FiducialOutlier& o = d.outliers[next++];
      const Location& location = set.locations[rows[k]];
      out.report.rejected.push_back(
          {location.point, location.config, o.deviation_sensor_m.norm(), o.sigmas, o.can_fill()});
    } else {
      out.registered.push_back(rows[k]);
    }
  }
  if (out.registered.size() < 3) fail(set, "robust check left fewer than 3 fiducials");
  return out;
}

void fill_model_fiducials(const MeasurementSet& set, const std::vector<std::size_t>& rows,
                          const RobustReport& report, const SimilarityTransform& T_robot_sensor,
                          RegistrationModel& model) {
  const Points3 sensor = set.sensor_points(rows);
  const Points3 robot = set.robot_points(rows);
  const Points3 eps = fiducial_corrections(T_robot_sensor, sensor, robot);  // Eq. 6, all rows
  std::vector<bool> dropped(rows.size(), false);
  Points3 kept_eps = eps;
  std::vector<Location> locations = locations_of(set, rows);
  for (const FiducialOutlier& o : report.detection.outliers) {
    const auto k = static_cast<std::size_t>(o.fiducial);
    if (!o.can_fill()) {
      dropped[k] = true;
      continue;
    }
    // Inlier neighbours only: their corrections are the final ones.
    const Eigen::Vector3d filled = o.fill(eps);
    kept_eps.col(o.fiducial) = filled;
    // X = R'(Y - tau)/s - eps (Eq. 6 solved for X): the reading the neighbours predict.
    locations[k].sensor_m = T_robot_sensor.inverse().apply(robot.col(o.fiducial)) - filled;
  }
  model.fiducials.clear();
  std::vector<Eigen::Index> columns;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (dropped[k]) continue;
    model.fiducials.push_back(locations[k]);
    columns.push_back(static_cast<Eigen::Index>(k));
  }
  model.corrections_sensor_m.resize(3, static_cast<Eigen::Index>(columns.size()));
  for (std::size_t i = 0; i < columns.size(); ++i) {
    model.corrections_sensor_m.col(static_cast<Eigen::Index>(i)) = kept_eps.col(columns[i]);
  }
}

}  // namespace vrreg::pipeline_detail
