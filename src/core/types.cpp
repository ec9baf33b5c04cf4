#include "vrreg/core/types.hpp"

namespace vrreg {

Points3 RigidTransform::apply_all(const ConstPoints3Ref& points_m) const {
  Points3 out = scale * (rotation * points_m);
  out.colwise() += translation_m;
  return out;
}

RigidTransform RigidTransform::inverse() const {
  RigidTransform inv;
  inv.rotation = rotation.transpose();
  inv.scale = 1.0 / scale;
  inv.translation_m = -(inv.scale * (inv.rotation * translation_m));
  return inv;
}

RigidTransform RigidTransform::operator*(const RigidTransform& other) const {
  RigidTransform out;
  out.rotation = rotation * other.rotation;
  out.scale = scale * other.scale;
  out.translation_m = scale * (rotation * other.translation_m) + translation_m;
  return out;
}

}  // namespace vrreg
