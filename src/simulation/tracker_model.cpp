// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/tracker_model.hpp"

#include <cmath>
#include <numbers>

#include "vrreg/core/check.hpp"

namespace vrreg::simulation {

void TrackerModel::validate() const {
  VRREG_THROW_UNLESS(std::isfinite(distance_m) && distance_m > 0.0,
                     "tracker model: distance must be positive (got " << distance_m << " m)");
  VRREG_THROW_UNLESS(std::isfinite(azimuth_rad), "tracker model: azimuth is not finite");
  VRREG_THROW_UNLESS(
      std::isfinite(elevation_rad) && std::abs(elevation_rad) < 0.5 * std::numbers::pi,
      "tracker model: elevation must be within (-90, 90) deg (got " << elevation_rad << " rad)");
  VRREG_THROW_UNLESS(noise_sigma_m.allFinite() && noise_sigma_m.minCoeff() >= 0.0,
                     "tracker model: noise sigma must be finite and >= 0 (got "
                         << noise_sigma_m.transpose() << " m)");
  VRREG_THROW_UNLESS(
      readings_per_location >= 1,
      "tracker model: readings per location must be >= 1 (got " << readings_per_location << ")");
}

RigidTransform tracker_pose(const TrackerModel& model,
                            const Eigen::Vector3d& volume_centre_robot_m) {
  model.validate();
  const double ce = std::cos(model.elevation_rad);
  const Eigen::Vector3d towards_tracker(ce * std::cos(model.azimuth_rad),
                                        ce * std::sin(model.azimuth_rad),
                                        std::sin(model.elevation_rad));
  // Sensor axes in the robot frame: z looks at the centre, x horizontal, y = z x x (downwards).
  const Eigen::Vector3d z = -towards_tracker;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitZ().cross(z).normalized();
  const Eigen::Vector3d y = z.cross(x);
  RigidTransform T_robot_sensor;
  T_robot_sensor.rotation.col(0) = x;
  T_robot_sensor.rotation.col(1) = y;
  T_robot_sensor.rotation.col(2) = z;
  T_robot_sensor.translation_m = volume_centre_robot_m + model.distance_m * towards_tracker;
  return T_robot_sensor;
}

Eigen::Vector3d tracker_reading(const RigidTransform& T_sensor_robot,
                                const Eigen::Vector3d& noise_sigma_m,
                                const Eigen::Vector3d& p_robot_m, Random& rng) {
  Eigen::Vector3d p = T_sensor_robot.apply(p_robot_m);
  for (int axis = 0; axis < 3; ++axis) p(axis) += rng.normal(noise_sigma_m(axis));
  return p;
}

}  // namespace vrreg::simulation
