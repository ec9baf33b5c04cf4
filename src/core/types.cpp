// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/types.hpp"

#include "vrreg/core/check.hpp"

namespace vrreg {

Eigen::Isometry3d RigidTransform::isometry() const {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = rotation;
  out.translation() = translation_m;
  return out;
}

Points3 RigidTransform::apply_all(const ConstPoints3Ref& points_m) const {
  Points3 out = rotation * points_m;
  out.colwise() += translation_m;
  return out;
}

RigidTransform RigidTransform::inverse() const {
  RigidTransform inv;
  inv.rotation = rotation.transpose();
  inv.translation_m = -(inv.rotation * translation_m);
  return inv;
}

RigidTransform RigidTransform::operator*(const RigidTransform& other) const {
  return {rotation * other.rotation, rotation * other.translation_m + translation_m};
}

RigidTransform SimilarityTransform::rigid() const {
  VRREG_THROW_UNLESS(scale == 1.0, "a similarity with scale " << scale
                                                              << " is not a rigid transform");
  return {rotation, translation_m};
}

Points3 SimilarityTransform::apply_all(const ConstPoints3Ref& points_m) const {
  Points3 out = scale * (rotation * points_m);
  out.colwise() += translation_m;
  return out;
}

SimilarityTransform SimilarityTransform::inverse() const {
  SimilarityTransform inv;
  inv.rotation = rotation.transpose();
  inv.scale = 1.0 / scale;
  inv.translation_m = -(inv.scale * (inv.rotation * translation_m));
  return inv;
}

SimilarityTransform operator*(const SimilarityTransform& a, const SimilarityTransform& b) {
  SimilarityTransform out;
  out.rotation = a.rotation * b.rotation;
  out.scale = a.scale * b.scale;
  out.translation_m = a.scale * (a.rotation * b.translation_m) + a.translation_m;
  return out;
}

}  // namespace vrreg
