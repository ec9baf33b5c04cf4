// SPDX-License-Identifier: Apache-2.0
// Joint-by-joint chains (URDF's form) to DH: with every joint at zero, the axis of joint i is a
// line (point, direction) in the base frame; DH frame i-1 has z on the axis of joint i, frame i's x
// along the common normal from axis i to axis i+1. What the DH table cannot hold (where frame 0
// sits in the base, where the tip sits on the last frame) goes to the base and tool transforms.
#include "vrreg/kinematics/joint_chain.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include "vrreg/core/check.hpp"

namespace vrreg::kinematics {
namespace {

// Below this (m, or sine of an angle) two axes count as parallel, or a point as on a line.
constexpr double kGeometryTolerance = 1e-12;

struct Line {
  Eigen::Vector3d point;
  Eigen::Vector3d direction;  // unit
};

// The unit vector of `v` projected off `z`, or `fallback` projected when `v` is along `z`.
Eigen::Vector3d perpendicular(const Eigen::Vector3d& v, const Eigen::Vector3d& z,
                              const Eigen::Vector3d& fallback) {
  Eigen::Vector3d p = v - v.dot(z) * z;
  if (p.norm() <= kGeometryTolerance) p = fallback - fallback.dot(z) * z;
  return p.normalized();
}

// Signed angle from `from` to `to` about `axis` (both perpendicular to it) [rad].
double angle_about(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                   const Eigen::Vector3d& axis) {
  return std::atan2(from.cross(to).dot(axis), from.dot(to));
}

Eigen::Isometry3d frame(const Eigen::Vector3d& origin, const Eigen::Vector3d& x,
                        const Eigen::Vector3d& z) {
  Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
  f.linear().col(0) = x;
  f.linear().col(1) = z.cross(x);
  f.linear().col(2) = z;
  f.translation() = origin;
  return f;
}

// The conversion leaves rounding of ~1e-16 on what the joint list states exactly (a twist of
// 90 deg, a link of 0.425 m): angles within 1e-12 rad of a multiple of 90 deg become that
// multiple, lengths are rounded to the femtometre (the nearest double to a decimal length), so
// that a chain built like a built-in robot has its DH table to the bit.
double snap_angle(double angle_rad) {
  const double quarter = std::numbers::pi / 2;
  const double k = std::round(angle_rad / quarter);
  return std::abs(angle_rad - k * quarter) <= 1e-12 ? k * quarter + 0.0 : angle_rad;
}

double snap_length(double length_m) { return std::round(length_m * 1e15) / 1e15 + 0.0; }

DhRow snapped(DhRow row) {
  row.a_m = snap_length(row.a_m);
  row.d_m = snap_length(row.d_m);
  row.alpha_rad = snap_angle(row.alpha_rad);
  row.theta_offset_rad = snap_angle(row.theta_offset_rad);
  return row;
}

Eigen::Isometry3d joint_motion(const ChainJoint& joint, double q) {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d axis = joint.axis.normalized();
  if (joint.type == JointType::kPrismatic) {
    m.translation() = q * axis;
  } else {
    m.linear() = Eigen::AngleAxisd(q, axis).toRotationMatrix();
  }
  return m;
}

// The DH row from frame i-1 (origin o, axes x, z on the axis of joint i) to the next axis; fills
// the next frame's origin and x.
DhRow next_row(const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& z,
               const Line& next, Eigen::Vector3d& o_next, Eigen::Vector3d& x_next) {
  DhRow row;
  const Eigen::Vector3d& z_next = next.direction;
  const Eigen::Vector3d cross = z.cross(z_next);
  const Eigen::Vector3d w = next.point - o;
  double d = 0.0;
  if (cross.norm() > kGeometryTolerance) {
    // Skew or intersecting axes: the common normal's feet o + s z and next.point + t z_next.
    const Eigen::Vector3d n = cross.normalized();
    const double s = w.cross(z_next).dot(cross) / cross.squaredNorm();
    const double t = w.cross(z).dot(cross) / cross.squaredNorm();
    d = s;
    o_next = next.point + t * z_next;
    x_next = n;
  } else {
    // Parallel axes: the normal through o (d = 0); on one line, x carries on.
    const Eigen::Vector3d v = w - w.dot(z) * z;
    o_next = o + v;
    x_next = v.norm() > kGeometryTolerance ? Eigen::Vector3d(v.normalized()) : x;
  }
  if (x_next.dot(x) < 0.0) x_next = -x_next;  // |theta offset| <= 90 deg
  row.d_m = d;
  row.a_m = (o_next - (o + d * z)).dot(x_next);
  row.theta_offset_rad = angle_about(x, x_next, z);
  row.alpha_rad = angle_about(z, z_next, x_next);
  return row;
}

}  // namespace

Eigen::Isometry3d joints_forward_kinematics(const std::vector<ChainJoint>& joints,
                                            const Eigen::Isometry3d& T_last_tip,
                                            const JointRef& q) {
  VRREG_THROW_UNLESS(
      q.size() == static_cast<Eigen::Index>(joints.size()),
      "joint chain FK: " << joints.size() << " joints, got " << q.size() << " values");
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < joints.size(); ++i) {
    t = t * joints[i].T_parent_joint * joint_motion(joints[i], q(static_cast<Eigen::Index>(i)));
  }
  return t * T_last_tip;
}

namespace {

// The DH chain of `axes` (joint axis lines at q = 0, base frame) with frame 0's x along
// `x0_sign` times the base's x (projected off axis 1).
SerialChain dh_chain(std::string name, const std::vector<ChainJoint>& joints,
                     const std::vector<Line>& axes, const Eigen::Isometry3d& T_base_tip,
                     double x0_sign) {
  const std::size_t n = joints.size();
  // Frame 0: on axis 1 at the foot of the base origin, x from the base's x.
  Eigen::Vector3d z = axes[0].direction;
  Eigen::Vector3d o = axes[0].point - axes[0].point.dot(z) * z;
  Eigen::Vector3d x =
      x0_sign * perpendicular(Eigen::Vector3d::UnitX(), z, Eigen::Vector3d::UnitY());
  const Eigen::Isometry3d T_base_dh0 = frame(o, x, z);

  std::vector<DhRow> rows;
  std::vector<JointLimits> limits;
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d o_next, x_next;
    DhRow row;
    if (i + 1 < n) {
      row = next_row(o, x, z, axes[i + 1], o_next, x_next);
    } else {
      // The last frame: z along the last axis, at the foot of the tip, x from the tip's x.
      o_next = o + (T_base_tip.translation() - o).dot(z) * z;
      x_next = perpendicular(T_base_tip.linear().col(0), z, T_base_tip.linear().col(1));
      row.d_m = (o_next - o).dot(z);
      row.theta_offset_rad = angle_about(x, x_next, z);
    }
    row.type = joints[i].type;
    rows.push_back(snapped(row));
    limits.push_back(joints[i].limits);
    const Eigen::Vector3d z_next = i + 1 < n ? axes[i + 1].direction : z;
    o = o_next;
    x = x_next;
    z = z_next;
  }
  const Eigen::Isometry3d T_base_flange = frame(o, x, z);
  Eigen::Isometry3d T_flange_tcp = T_base_flange.inverse(Eigen::Isometry) * T_base_tip;
  // Rounding leaves ~1e-16 where the tip is the flange: keep an exact identity there, so that
  // poses read "flange" and no tool transform is applied.
  if ((T_flange_tcp.matrix() - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff() <= 1e-14) {
    T_flange_tcp = Eigen::Isometry3d::Identity();
  }
  Eigen::Isometry3d base = T_base_dh0;
  if ((base.matrix() - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff() <= 1e-14) {
    base = Eigen::Isometry3d::Identity();
  }
  return SerialChain(std::move(name), std::move(rows), std::move(limits), base, T_flange_tcp);
}

}  // namespace

SerialChain chain_from_joints(std::string name, const std::vector<ChainJoint>& joints,
                              const Eigen::Isometry3d& T_last_tip) {
  const std::size_t n = joints.size();
  VRREG_THROW_UNLESS(
      n >= 1 && n <= static_cast<std::size_t>(kMaxJoints),
      "robot '" << name << "': a chain needs 1 to " << kMaxJoints << " moving joints, got " << n);
  // Every joint's axis line at q = 0, in the base frame.
  std::vector<Line> axes;
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (const ChainJoint& j : joints) {
    VRREG_THROW_UNLESS(j.axis.allFinite() && j.axis.norm() > 1e-9,
                       "robot '" << name << "': joint '" << j.name << "' has no axis direction ("
                                 << j.axis.transpose() << ")");
    t = t * j.T_parent_joint;
    axes.push_back({t.translation(), (t.linear() * j.axis.normalized()).normalized()});
  }
  const Eigen::Isometry3d T_base_tip = t * T_last_tip;
  SerialChain chain = dh_chain(name, joints, axes, T_base_tip, 1.0);
  // Every x after frame 0 follows frame 0's sign, and the UR and LWR 4+ structures fix the signs
  // of the twists: a base frame turned half a turn about axis 1 (ROS-Industrial's base_link
  // beside "base") gives the same arm with every twist negated. The other sign then gives the
  // analytic IK, with the half turn in the base transform.
  if (chain.family() == ChainFamily::kGeneric) {
    SerialChain flipped = dh_chain(name, joints, axes, T_base_tip, -1.0);
    if (flipped.family() != ChainFamily::kGeneric) return flipped;
  }
  return chain;
}

}  // namespace vrreg::kinematics
