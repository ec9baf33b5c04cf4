// SPDX-License-Identifier: Apache-2.0
#pragma once
// An arm on a linear axis: a UR5 whose base a carriage slides along the robot's x axis (joint 1,
// metres), with a periodic error of the carriage's position (a rack's or a ball screw's ripple).
// Fiducials measured at a few carriage positions leave the carriage's error between them
// unmeasured: the case for judging the joint model's support in joint space, not only by each
// joint's range (docs/joint-space-model.md).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::simulation {

/// A UR5 on a 2 m rail: joint 1 slides the arm's base from x = -1 m (0) to 1 m (2), 0.25 m above
/// the floor, 0.5 m off the robot frame's x axis; joints 2-7 are the UR5's; TCP on the flange.
kinematics::SerialChain ur5_on_rail();

/// The rail's test bed: ur5_on_rail() with a tool 0.1 m along the flange's z, pointing down;
/// errors: small DH errors, the carriage's ripple `ripple_amplitude_m` sin(2 pi s /
/// `ripple_period_m` + phase) [m], 0.01 mm repeatability; a tracker 2.4 m away, 0.02 mm noise
/// per axis, 3 readings per location.
Testbed rail_testbed(double ripple_amplitude_m = 0.15e-3, double ripple_period_m = 0.25);

struct RailCellOptions {
  /// Carriage positions the fiducials are measured at [m]; at each, a 5 x 3 x 3 lattice (75,
  /// 100, 100 mm) around (0, 0, 0.2) m, the same points from every position.
  std::vector<double> stations_m{0.7, 1.0, 1.3};
  int targets = 40;  ///< inside the lattice's box, carriage uniform in [target_lo_m, target_hi_m]
  double target_lo_m = 0.75;
  double target_hi_m = 1.25;
  double ripple_amplitude_m = 0.15e-3;
  double ripple_period_m = 0.25;
  std::uint64_t seed = 1;  ///< the robot's errors, the targets and the noise
};

/// A rail cell: nominal positions, averaged readings and commanded joints of its fiducials and
/// targets, and the commanded robot (ur5_on_rail() with the test bed's tool).
struct RailCell {
  kinematics::SerialChain robot;
  Points3 fiducials_robot_m{};
  Points3 fiducials_sensor_m{};
  Eigen::MatrixXd fiducials_q_rad{};
  Points3 targets_robot_m{};
  Points3 targets_sensor_m{};
  Eigen::MatrixXd targets_q_rad{};
  double noise_sd_m = 0.0;  ///< of one averaged reading per axis [m]
};

/// Measures the rail cell of `options` on rail_testbed() (same options, same cell).
RailCell rail_cell(const RailCellOptions& options);

}  // namespace vrreg::simulation
