// SPDX-License-Identifier: Apache-2.0
#pragma once
// Point sets, rigid transforms and similarities. SI inside the library: metres, radians
// (design.md 1).
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "vrreg/config.hpp"

namespace vrreg {

/// A set of 3D points, one column a point.
using Points3 = Eigen::Matrix3Xd;
/// Read-only view of a point set, for non-template functions.
using ConstPoints3Ref = Eigen::Ref<const Eigen::Matrix3Xd>;

/// A rigid transform y = R x + t (a proper rotation and a translation). Named T_<to>_<from>.
struct RigidTransform {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();

  RigidTransform() = default;
  /// From a rotation R and a translation t [m] (paper Eq. 2's {R, tau}).
  RigidTransform(const Eigen::Matrix3d& rotation_, const Eigen::Vector3d& translation_m_)
      : rotation(rotation_), translation_m(translation_m_) {}
  /// From an Eigen isometry (its linear part must be a rotation).
  explicit RigidTransform(const Eigen::Isometry3d& isometry)
      : rotation(isometry.linear()), translation_m(isometry.translation()) {}
  /// As an Eigen isometry.
  [[nodiscard]] Eigen::Isometry3d isometry() const;

  /// Maps one point from the `from` frame to the `to` frame [m].
  [[nodiscard]] Eigen::Vector3d apply(const Eigen::Vector3d& point_m) const {
    return rotation * point_m + translation_m;
  }
  /// Maps every column of `points_m` (a separate name: a column would make `apply` ambiguous).
  [[nodiscard]] Points3 apply_all(const ConstPoints3Ref& points_m) const;
  /// The inverse map (paper Eq. 6: R_inv = R', tau_inv = -R' tau).
  [[nodiscard]] RigidTransform inverse() const;
  /// Composition: (this * other).apply(x) == this->apply(other.apply(x)).
  [[nodiscard]] RigidTransform operator*(const RigidTransform& other) const;
};

/// A similarity y = s R x + t: what registration returns when it also fits a uniform scale (not the
/// paper's default; scale is 1 otherwise). A rigid transform converts to one with scale 1.
struct SimilarityTransform {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  double scale = 1.0;

  SimilarityTransform() = default;
  /// The rigid transform `rigid` with a scale (1: the same map).
  SimilarityTransform(const RigidTransform& rigid, double scale_ = 1.0)  // NOLINT: implicit
      : rotation(rigid.rotation), translation_m(rigid.translation_m), scale(scale_) {}
  /// The rigid transform it is; throws InputError unless the scale is 1.
  [[nodiscard]] RigidTransform rigid() const;

  /// Maps one point from the `from` frame to the `to` frame [m].
  [[nodiscard]] Eigen::Vector3d apply(const Eigen::Vector3d& point_m) const {
    return scale * (rotation * point_m) + translation_m;
  }
  /// Maps every column of `points_m`.
  [[nodiscard]] Points3 apply_all(const ConstPoints3Ref& points_m) const;
  /// The inverse map (Eq. 6, divided by the scale).
  [[nodiscard]] SimilarityTransform inverse() const;
};

/// Composition of similarities (or a rigid transform with a similarity, either side):
/// (a * b).apply(x) == a.apply(b.apply(x)).
[[nodiscard]] SimilarityTransform operator*(const SimilarityTransform& a,
                                           const SimilarityTransform& b);

}  // namespace vrreg
