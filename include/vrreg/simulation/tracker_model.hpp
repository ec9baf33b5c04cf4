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

  /// Throws InputError on non-finite or negative values, K < 1, |elevation| >= 90 deg.
  void validate() const;
};

/// T_robot_sensor of the tracker: sensor origin at distance_m from `volume_centre_robot_m` in
/// the model's direction, sensor z axis looking at the centre, sensor x axis horizontal.
RigidTransform tracker_pose(const TrackerModel& model,
                            const Eigen::Vector3d& volume_centre_robot_m);

/// One reading of point `p_robot_m` [m, robot frame]: T_sensor_robot p plus per-axis noise [m].
Eigen::Vector3d tracker_reading(const RigidTransform& T_sensor_robot,
                                const Eigen::Vector3d& noise_sigma_m,
                                const Eigen::Vector3d& p_robot_m, Random& rng);

}  // namespace vrreg::simulation
