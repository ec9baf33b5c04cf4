// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to correction: cylindrical coordinates about the robot's base axis (the robot frame's
// z axis, joint 1 of the UR5 and the LWR 4+), in which a serial arm's position error is smooth
// and closer to stationary than in Cartesian axes: the base joint's and the shoulder's errors
// vary along the azimuth and the radius, not along x and y (docs/field-models.md).
#include <optional>

#include "vrreg/core/types.hpp"

namespace vrreg::detail {

class BaseCylinder {
 public:
  /// The frame for fiducials at `robot_m` (3 x J, robot frame [m]), or nullopt when cylindrical
  /// coordinates do not suit them: a fiducial within 20 % of the mean radius of the axis (the
  /// azimuth is ill-defined there) or fiducials all around the axis, leaving no empty sector
  /// of 60 degrees for the azimuth's cut (the field would be split there). The azimuth is
  /// measured from the middle of the fiducials' sector.
  static std::optional<BaseCylinder> fit(const ConstPoints3Ref& robot_m);

  /// (radius, mean radius x azimuth from the middle of the sector, z) [m]: all three in metres so a
  /// kernel's length scales mean the same along each.
  [[nodiscard]] Points3 coordinates(const ConstPoints3Ref& robot_m) const;
  /// Robot-frame vectors `v` at `robot_m` in (radial, tangential, z) components, and back.
  [[nodiscard]] Points3 to_local(const ConstPoints3Ref& robot_m, const ConstPoints3Ref& v) const;
  [[nodiscard]] Points3 from_local(const ConstPoints3Ref& robot_m,
                                   const ConstPoints3Ref& v_local) const;
  [[nodiscard]] double mean_radius_m() const { return mean_radius_m_; }

 private:
  BaseCylinder(double mean_radius_m, double reference_azimuth_rad)
      : mean_radius_m_(mean_radius_m), reference_azimuth_rad_(reference_azimuth_rad) {}
  double mean_radius_m_;
  double reference_azimuth_rad_;
};

}  // namespace vrreg::detail
