// SPDX-License-Identifier: Apache-2.0
#pragma once
// An OptiTrack-like motion tracker: a fixed sensor frame looking at the work volume from a
// distance, Gaussian noise on every reading, K readings per visited location.
#include <Eigen/Core>

#include "vrreg/core/random.hpp"
#include "vrreg/core/types.hpp"

namespace vrreg::simulation {

/// Where the tracker stands and how it measures. SI: m, rad.
struct TrackerModel {
  /// Distance from the tracker (sensor-frame origin) to the centre of the work volume [m].
  double distance_m = 2.1;
  /// Direction from the volume centre to the tracker: azimuth about the base z axis from +x.
  double azimuth_rad = 0.0;
  /// Direction from the volume centre to the tracker: elevation above the base xy-plane.
  double elevation_rad = 0.0;
  /// Gaussian noise of one reading, per sensor axis (x, y; z = viewing direction) [m].
  Eigen::Vector3d noise_sigma_m = Eigen::Vector3d::Constant(0.058e-3);
  /// Readings K per visited location (repeat readings of a standing arm).
  int readings_per_location = 12;
  /// A rigid body of `rigid_body_markers` spheres evenly on a circle of this radius about the
  /// tracked point, in the plane normal to the tool's z axis: the tracker then reports its
  /// orientation too (OptiTrack's rigid bodies) [m]. 0: one sphere, positions only.
  double rigid_body_radius_m = 0.0;
  int rigid_body_markers = 4;  ///< spheres of the rigid body (>= 3)

  /// Throws InputError on non-finite or negative values, K < 1, |elevation| >= 90 deg.
  void validate() const;
};

/// The orientation noise of one rigid-body reading per body axis (x, y in the body's plane, z
/// normal to it) [rad]: a least-squares fit of N spheres on a circle of radius r, each read with
/// the position noise sigma (the RMS of noise_sigma_m's axes), turns by sigma / sqrt(sum of the
/// spheres' squared distances from the axis): sigma / (r sqrt(N / 2)) in the plane,
/// sigma / (r sqrt(N)) about the normal. Zero without a rigid body.
Eigen::Vector3d orientation_noise_sigma_rad(const TrackerModel& model);

/// One orientation reading of a body at `R_robot_marker` (robot frame): R_sensor_robot
/// R_robot_marker exp(n), n Gaussian per body axis with `sigma_rad`.
Eigen::Quaterniond tracker_orientation_reading(const RigidTransform& T_sensor_robot,
                                               const Eigen::Vector3d& sigma_rad,
                                               const Eigen::Matrix3d& R_robot_marker, Random& rng);

/// T_robot_sensor of the tracker: sensor origin at distance_m from `volume_centre_robot_m` in
/// the model's direction, sensor z axis looking at the centre, sensor x axis horizontal.
RigidTransform tracker_pose(const TrackerModel& model,
                            const Eigen::Vector3d& volume_centre_robot_m);

/// One reading of point `p_robot_m` [m, robot frame]: T_sensor_robot p plus per-axis noise [m].
Eigen::Vector3d tracker_reading(const RigidTransform& T_sensor_robot,
                                const Eigen::Vector3d& noise_sigma_m,
                                const Eigen::Vector3d& p_robot_m, Random& rng);

}  // namespace vrreg::simulation
