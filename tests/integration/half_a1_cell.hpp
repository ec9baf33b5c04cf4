// SPDX-License-Identifier: Apache-2.0
#pragma once
// The lost-motion tests' UR5 cell: A1 (25 mm lattice, visited row by row, every odd node a
// target) in the half of the volume with grid index x <= 5, the test bed's smooth DH errors,
// repeatability and tracker noise, no transmission error, and lost motion `lost_motion_rad`;
// the joints' approach directions from the visiting order.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::testing {

// The simulation of the UR5 test bed (seed 2) without its transmission error, with lost motion
// `lost_motion_rad` (empty: none).
inline simulation::SimulationOptions ur5_lost_motion_options(
    const std::vector<double>& lost_motion_rad) {
  simulation::SimulationOptions o;
  o.seed = 2;
  o.errors = simulation::ur5_testbed().default_errors;
  o.errors->robot.transmission_amplitude_rad.clear();
  o.errors->robot.transmission_period_rad.clear();
  o.errors->robot.lost_motion_rad = lost_motion_rad;
  return o;
}

inline MeasurementSet half_a1_cell(const std::vector<double>& lost_motion_rad) {
  const MeasurementSet set = experiments::to_measurement_set(simulation::simulate_dataset(
      simulation::ur5_testbed(), simulation::Dataset::kA1, ur5_lost_motion_options(lost_motion_rad)));
  MeasurementSet kept = set;
  kept.locations.clear();
  for (const Location& loc : set.locations) {
    Eigen::Vector3i n;
    EXPECT_EQ(std::sscanf(loc.point.c_str(), "p%d_%d_%d", &n.x(), &n.y(), &n.z()), 3);
    if (n.x() <= 5) kept.locations.push_back(loc);
  }
  return kept;
}

}  // namespace vrreg::testing
