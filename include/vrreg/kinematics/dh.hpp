// SPDX-License-Identifier: Apache-2.0
#pragma once
// One row of a standard (distal) Denavit-Hartenberg table and the link transform it defines.
#include <Eigen/Geometry>
#include <cmath>

namespace vrreg::kinematics {

/// Standard DH row: A_i(q) = Rz(q + theta_offset) * Tz(d) * Tx(a) * Rx(alpha), frame i-1 -> i.
struct DhRow {
  double a_m = 0.0;               ///< link length along x_i [m]
  double alpha_rad = 0.0;         ///< link twist about x_i [rad]
  double d_m = 0.0;               ///< link offset along z_{i-1} [m]
  double theta_offset_rad = 0.0;  ///< joint zero offset about z_{i-1} [rad]: theta = q + offset
};

/// The link transform T_{i-1}_{i} of `row` at joint angle `q_rad` [rad].
inline Eigen::Isometry3d dh_transform(const DhRow& row, double q_rad) {
  const double theta = q_rad + row.theta_offset_rad;
  const double ct = std::cos(theta);
  const double st = std::sin(theta);
  const double ca = std::cos(row.alpha_rad);
  const double sa = std::sin(row.alpha_rad);
  Eigen::Isometry3d t;
  t.linear() << ct, -st * ca, st * sa,  //
      st, ct * ca, -ct * sa,            //
      0.0, sa, ca;
  t.translation() << row.a_m * ct, row.a_m * st, row.d_m;
  t.makeAffine();
  return t;
}

}  // namespace vrreg::kinematics
