// SPDX-License-Identifier: Apache-2.0
#pragma once
// Time in a simulated cell: the tracker bumped at a given time, the robot's links growing as it
// warms up and with the day's temperature (read_locations.hpp reads the cell at any time).
#include <Eigen/Core>
#include <cstdint>
#include <limits>

#include "vrreg/core/random.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/simulation/simulated_robot.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg/simulation/tracker_model.hpp"

namespace vrreg::simulation {

/// Relative growth of the robot's links over time: a warm-up g_w (1 - exp(-t / tau)) from a cold
/// start and a daily swing g_d sin(2 pi t / day). SI: s.
struct ThermalModel {
  double warmup_growth = 0.0;              ///< g_w, the steady state's growth over cold
  double warmup_time_constant_s = 1800.0;  ///< tau
  double daily_growth = 0.0;               ///< g_d, amplitude of the day's swing
  double daily_period_s = 86400.0;
  /// The growth at time `t_s` after a cold start (RobotErrorModel::link_growth).
  [[nodiscard]] double growth_at(double t_s) const;
  /// Throws InputError on non-finite values, tau or the period <= 0, or |growth| >= 0.01.
  void validate() const;
};

/// What happens to a cell after it was registered (time 0).
struct CellEvents {
  ThermalModel thermal{};
  double bump_time_s = std::numeric_limits<double>::infinity();  ///< when the tracker is bumped
  /// The bump's size: RMS displacement over the corners of a 0.3 m cube at the work volume's
  /// centre [m]; its direction is drawn from the seed (testbed_bump), the same at every time.
  double bump_rms_m = 0.0;
  /// Throws InputError on a negative or non-finite size, a NaN time or a bad thermal model.
  void validate() const;
};

/// The bump `seed` draws on `testbed` with the tracker at `T_robot_sensor`, of size `rms_m`:
/// T_after_before (coordinates before the bump -> after it).
RigidTransform testbed_bump(const Testbed& testbed, const RigidTransform& T_robot_sensor,
                            double rms_m, std::uint64_t seed);

/// A random bump of the tracker (rotation about a random axis through a random point near the
/// cell, plus a translation) scaled so that the RMS displacement of `cell_sensor_m` [m, sensor
/// frame] is `rms_m`: returns T_after_before (coordinates before the bump -> after it).
RigidTransform draw_bump(const ConstPoints3Ref& cell_sensor_m, double rms_m, Random& rng);

/// The link growth that moves the robot's TCP by `rms_m` RMS over the commanded joints `q_rad`
/// (one column per pose) relative to `robot` (its growth as the reference) [m]; the growth is
/// found on the linear response to a small trial growth.
double growth_for_displacement(const SimulatedRobot& robot, const Eigen::MatrixXd& q_rad,
                               double rms_m);

/// `robot` with its links grown by `growth` (RobotErrorModel::link_growth).
SimulatedRobot grown(const SimulatedRobot& robot, double growth);

}  // namespace vrreg::simulation
