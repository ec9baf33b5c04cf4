// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/tracker_model.hpp"

#include <cmath>
#include <numbers>

#include "vrreg/core/check.hpp"
#include "vrreg/core/rotation.hpp"

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
  VRREG_THROW_UNLESS(std::isfinite(rigid_body_radius_m) && rigid_body_radius_m >= 0.0,
                     "tracker model: the rigid body's radius must be finite and >= 0 (got "
                         << rigid_body_radius_m << " m)");
  VRREG_THROW_UNLESS(
      rigid_body_radius_m == 0.0 || rigid_body_markers >= 3,
      "tracker model: a rigid body needs at least 3 spheres (got " << rigid_body_markers << ")");
}

Eigen::Vector3d orientation_noise_sigma_rad(const TrackerModel& model) {
  if (model.rigid_body_radius_m == 0.0) return Eigen::Vector3d::Zero();
  const double sigma_m = std::sqrt(model.noise_sigma_m.squaredNorm() / 3.0);
  const double n = model.rigid_body_markers;
  const double r = model.rigid_body_radius_m;
  const double in_plane = sigma_m / (r * std::sqrt(0.5 * n));
  return {in_plane, in_plane, sigma_m / (r * std::sqrt(n))};
}

Eigen::Quaterniond tracker_orientation_reading(const RigidTransform& T_sensor_robot,
                                               const Eigen::Vector3d& sigma_rad,
                                               const Eigen::Matrix3d& R_robot_marker, Random& rng) {
  const double nx = rng.normal(sigma_rad.x());  // in this order: reproducible draws
  const double ny = rng.normal(sigma_rad.y());
  const double nz = rng.normal(sigma_rad.z());
  const Eigen::Matrix3d R_sensor_marker =
      T_sensor_robot.rotation * R_robot_marker * rotation_exp(Eigen::Vector3d(nx, ny, nz));
  return Eigen::Quaterniond(R_sensor_marker).normalized();
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
