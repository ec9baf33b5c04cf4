// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/strategy3_registration.hpp"

#include <cassert>
#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/correction/corner_candidates.hpp"
#include "vrreg/correction/rrbc.hpp"

namespace vrreg::planning {

void Strategy3Options::validate() const {
  VRREG_THROW_UNLESS(
      std::isfinite(match_tolerance_m) && match_tolerance_m > 0.0,
      "Strategy 3: the match tolerance must be > 0, got " << match_tolerance_m << " m");
  registration.validate();
}

Strategy3Registration register_volume_corners(const std::vector<Location>& fiducials,
                                              const Strategy3Options& options) {
  options.validate();
  VRREG_THROW_UNLESS(fiducials.size() >= 8,
                     "Strategy 3 needs fiducials at the 8 corners of the "
                     "work volume, got "
                         << fiducials.size() << " fiducials");
  Points3 robot(3, static_cast<Eigen::Index>(fiducials.size()));
  Points3 sensor(3, robot.cols());
  for (std::size_t j = 0; j < fiducials.size(); ++j) {
    VRREG_THROW_UNLESS(fiducials[j].has_robot, "Strategy 3: fiducial '"
                                                   << fiducials[j].point
                                                   << "' has no nominal robot position");
    robot.col(static_cast<Eigen::Index>(j)) = fiducials[j].robot_m;
    sensor.col(static_cast<Eigen::Index>(j)) = fiducials[j].sensor_m;
  }
  const CornerCandidates candidates(robot, options.match_tolerance_m);
  const CornerFiducials corners = candidates.volume_corners();

  Strategy3Registration out;
  Random rng(options.seed);
  Points3 corner_robot(3, 8);
  Points3 corner_sensor(3, 8);
  for (std::size_t c = 0; c < 8; ++c) {
    const std::vector<Eigen::Index>& at = corners[c];
    assert(!at.empty());  // the nearest position always holds its own fiducial
    const Eigen::Index j = at[static_cast<std::size_t>(rng.below(at.size()))];
    out.corner_fiducials[c] = static_cast<std::size_t>(j);
    corner_robot.col(static_cast<Eigen::Index>(c)) = robot.col(j);
    corner_sensor.col(static_cast<Eigen::Index>(c)) = sensor.col(j);
  }
  out.registration = register_rigid(corner_sensor, corner_robot, options.registration);
  out.corrections_sensor_m = fiducial_corrections(out.registration.T_robot_sensor, sensor, robot);
  return out;
}

}  // namespace vrreg::planning
