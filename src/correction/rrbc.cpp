// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/rrbc.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg {

Points3 fiducial_corrections(const SimilarityTransform& T_robot_sensor,
                             const ConstPoints3Ref& fiducials_sensor_m,
                             const ConstPoints3Ref& fiducials_robot_m) {
  VRREG_THROW_UNLESS(fiducials_sensor_m.cols() == fiducials_robot_m.cols(),
                     "fiducial corrections need the same fiducials in both frames: "
                         << fiducials_sensor_m.cols() << " sensor vs " << fiducials_robot_m.cols()
                         << " robot positions");
  VRREG_THROW_UNLESS(fiducials_sensor_m.allFinite() && fiducials_robot_m.allFinite(),
                     "fiducial corrections: non-finite fiducial coordinates");
  VRREG_THROW_UNLESS(
      T_robot_sensor.rotation.allFinite() && T_robot_sensor.translation_m.allFinite() &&
          std::isfinite(T_robot_sensor.scale) && T_robot_sensor.scale > 0.0,
      "fiducial corrections: the transform is not finite (scale " << T_robot_sensor.scale << ")");
  // Eq. 6: epsilon_j = R_inv Y_j + tau_inv - X_j with R_inv = R'/s, tau_inv = -R' tau / s.
  const SimilarityTransform T_sensor_robot = T_robot_sensor.inverse();
  Points3 corrections_sensor_m(3, fiducials_sensor_m.cols());
  for (Eigen::Index j = 0; j < fiducials_sensor_m.cols(); ++j) {
    corrections_sensor_m.col(j) =
        T_sensor_robot.apply(Eigen::Vector3d(fiducials_robot_m.col(j))) - fiducials_sensor_m.col(j);
  }
  return corrections_sensor_m;
}

const char* to_string(StencilStatus status) {
  switch (status) {
    case StencilStatus::kOk:
      return "ok";
    case StencilStatus::kOutsideGrid:
      return "outside grid";
    case StencilStatus::kOutsideHull:
      return "outside hull";
    case StencilStatus::kMissingCorner:
      return "missing corner";
    case StencilStatus::kOutsideSupport:
      return "outside support";
    case StencilStatus::kExtrapolated:
      return "extrapolated";
    case StencilStatus::kTooFewFiducials:
      return "too few fiducials";
    case StencilStatus::kNotBetterThanNone:
      return "correction not better than none";
    case StencilStatus::kFlatLayout:
      return "flat layout";
  }
  return "unknown";
}

}  // namespace vrreg
