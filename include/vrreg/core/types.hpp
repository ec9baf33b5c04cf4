#pragma once
// Point sets and rigid transforms. SI inside the library: metres, radians (design.md 1).
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vrreg {

/// A set of 3D points, one column a point.
using Points3 = Eigen::Matrix3Xd;
/// Read-only view of a point set, for non-template functions.
using ConstPoints3Ref = Eigen::Ref<const Eigen::Matrix3Xd>;

/// A similarity y = scale * R * x + t; scale is 1 for a rigid transform. Named T_<to>_<from>.
struct RigidTransform {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  double scale = 1.0;

  /// Maps one point from the `from` frame to the `to` frame [m].
  [[nodiscard]] Eigen::Vector3d apply(const Eigen::Vector3d& point_m) const {
    return scale * (rotation * point_m) + translation_m;
  }
  /// Maps every column of `points_m` (a separate name: a column would make `apply` ambiguous).
  [[nodiscard]] Points3 apply_all(const ConstPoints3Ref& points_m) const;
  /// The inverse map (paper Eq. 6: R_inv = R', tau_inv = -R' tau, divided by the scale).
  [[nodiscard]] RigidTransform inverse() const;
  /// Composition: (this * other).apply(x) == this->apply(other.apply(x)).
  [[nodiscard]] RigidTransform operator*(const RigidTransform& other) const;
};

}  // namespace vrreg
