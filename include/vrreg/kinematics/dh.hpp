// SPDX-License-Identifier: Apache-2.0
#pragma once
// One row of a standard (distal) Denavit-Hartenberg table and the link transform it defines.
#include <Eigen/Geometry>
#include <cmath>

namespace vrreg::kinematics {

/// How joint i moves link i: turning about z_{i-1} or sliding along it.
enum class JointType : unsigned char {
  kRevolute,   ///< q [rad] adds to theta
  kPrismatic,  ///< q [m] adds to d
};

/// Standard DH row: A_i(q) = Rz(q + theta_offset) * Tz(d) * Tx(a) * Rx(alpha), frame i-1 -> i
/// (prismatic: Rz(theta_offset) * Tz(d + q) * Tx(a) * Rx(alpha)).
struct DhRow {
  double a_m = 0.0;               ///< link length along x_i [m]
  double alpha_rad = 0.0;         ///< link twist about x_i [rad]
  double d_m = 0.0;               ///< link offset along z_{i-1} [m] (prismatic: at q = 0)
  double theta_offset_rad = 0.0;  ///< joint zero offset about z_{i-1} [rad]: theta = q + offset
  JointType type = JointType::kRevolute;  ///< what the joint variable q moves

  [[nodiscard]] bool prismatic() const { return type == JointType::kPrismatic; }
};

/// The link transform T_{i-1}_{i} of `row` at joint value `q` [rad, or m if prismatic].
inline Eigen::Isometry3d dh_transform(const DhRow& row, double q) {
  const bool slides = row.prismatic();
  const double theta = slides ? row.theta_offset_rad : q + row.theta_offset_rad;
  const double d = slides ? row.d_m + q : row.d_m;
  const double ct = std::cos(theta);
  const double st = std::sin(theta);
  const double ca = std::cos(row.alpha_rad);
  const double sa = std::sin(row.alpha_rad);
  Eigen::Isometry3d t;
  t.linear() << ct, -st * ca, st * sa,  //
      st, ct * ca, -ct * sa,            //
      0.0, sa, ca;
  t.translation() << row.a_m * ct, row.a_m * st, d;
  t.makeAffine();
  return t;
}

}  // namespace vrreg::kinematics
