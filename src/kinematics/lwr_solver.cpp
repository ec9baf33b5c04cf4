// SPDX-License-Identifier: Apache-2.0
// LWR 4+ arm-angle IK (after Shimizu et al. 2008, re-derived for this DH table):
//   shoulder S = (0, 0, d1), wrist W = p - d7 z7, theta4 from |W - S| (law of cosines);
//   reference: theta3 = 0, theta1 = atan2 of W - S in the base xy-plane, theta2 from the planar
//   triangle; R03(psi) = R_u(psi) R03_ref (Rodrigues about u = (W - S)/|W - S|);
//   theta1..3 from R03 = P(t1) M(t2) M(t3) and theta5..7 from R47 = (R03 R34)^T R = P M Rz, where
//   P(t) = Rz(t) Rx(pi/2), M(t) = Rz(t) Rx(-pi/2). theta3 and theta7 are computed last from the
//   others as computed, so that rounding cancels and singular cases stay exact.
#include "lwr_solver.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "length_text.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/joint_vector.hpp"

namespace vrreg::kinematics::detail {
namespace {

using units::kPi;

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d k;
  k << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return k;
}

// First two columns of P(a) M(b) (the same pattern for R02 and R46).
void pm_columns(double a, double b, Eigen::Vector3d& col0, Eigen::Vector3d& col1) {
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
  col0 << ca * cb, sa * cb, sb;
  col1 << -sa, ca, 0.0;
}

// Solves R = P(a) M(b) X(c) for the branch b in [0, pi], where X(c) is Rz(c) or M(c): both have
// column 0 = (cos c, sin c, 0). Uses column 0 of R and the z axis of P(a) M(b), which is
// (-cos a sin b, -sin a sin b, cos b) and must be passed as column 2 of `r` (for X = Rz it is
// column 2 of R, for X = M it is -column 1). c comes last, from a and b as computed.
// `free_c` is c at a singularity (sin b ~ 0). Returns true when singular.
bool solve_pm(const Eigen::Matrix3d& r, double tolerance, double free_c, double& a, double& b,
              double& c) {
  const double sb_abs = std::sqrt(r(0, 2) * r(0, 2) + r(1, 2) * r(1, 2));
  b = std::atan2(sb_abs, r(2, 2));
  const bool singular = sb_abs <= tolerance;
  if (!singular) {
    a = std::atan2(-r(1, 2), -r(0, 2));
  } else if (r(2, 2) > 0.0) {
    a = std::atan2(r(1, 0), r(0, 0)) - free_c;  // P(a) M(0) Rz(c) = Rz(a + c)
  } else {
    a = std::atan2(-r(1, 0), -r(0, 0)) + free_c;  // P(a) M(pi) Rz(c) = Rz(a - c) Ry(pi)
  }
  Eigen::Vector3d col0, col1;
  pm_columns(a, b, col0, col1);
  c = std::atan2(col1.dot(r.col(0)), col0.dot(r.col(0)));
  return singular;
}

}  // namespace

LwrGeometry lwr_geometry(const SerialChain& chain, const char* what) {
  VRREG_THROW_UNLESS(chain.family() == ChainFamily::kLwr,
                     what << ": robot '" << chain.name()
                          << "' does not have the LWR 4+ structure (7 joints, a = 0, d2 = d4 = "
                             "d6 = 0, alpha = [90, -90, -90, 90, 90, -90, 0] deg); its family is "
                          << to_string(chain.family()));
  LwrGeometry g;
  g.d_bs = chain.row(0).d_m;
  g.d_se = chain.row(2).d_m;
  g.d_ew = chain.row(4).d_m;
  g.d_wf = chain.row(6).d_m;
  for (int i = 0; i < 7; ++i) g.offset[i] = chain.row(i).theta_offset_rad;
  return g;
}

LwrPoseFrame lwr_pose_frame(const LwrGeometry& g, const Eigen::Matrix3d& r,
                            const Eigen::Vector3d& p, double singular_tolerance,
                            double reach_tolerance_m) {
  LwrPoseFrame f;
  f.r = r;
  const Eigen::Vector3d wrist = p - g.d_wf * r.col(2);
  const Eigen::Vector3d x_sw = wrist - Eigen::Vector3d(0.0, 0.0, g.d_bs);
  const double length = x_sw.norm();
  const double reach_max = std::abs(g.d_se) + std::abs(g.d_ew);
  const double reach_min = std::abs(std::abs(g.d_se) - std::abs(g.d_ew));
  if (length > reach_max + reach_tolerance_m || length < reach_min - reach_tolerance_m ||
      length == 0.0) {
    // The squares in norm() overflow for a far target; hypot does not.
    const double distance =
        std::isfinite(length) ? length : std::hypot(x_sw.x(), x_sw.y(), x_sw.z());
    f.message = "the wrist centre is " + mm(distance) + " from the shoulder, outside the reach [" +
                mm(reach_min) + ", " + mm(reach_max) + "]";
    return f;
  }
  f.reachable = true;
  f.offset3 = g.offset[2];
  f.offset7 = g.offset[6];
  f.u = x_sw / length;
  // theta4 (|W - S|^2 = d_se^2 + d_ew^2 + 2 d_se d_ew cos theta4), base configuration >= 0.
  const double c4 = std::clamp(
      (length * length - g.d_se * g.d_se - g.d_ew * g.d_ew) / (2.0 * g.d_se * g.d_ew), -1.0, 1.0);
  const double s4 = std::sqrt(std::max(0.0, 1.0 - c4 * c4));
  f.theta4 = std::atan2(s4, c4);
  if (1.0 - std::abs(c4) <= singular_tolerance) f.singular |= kElbowSingular;
  f.r34 << c4, 0.0, s4, s4, 0.0, -c4, 0.0, 1.0, 0.0;  // P(theta4)

  // Reference elbow: theta3 = 0. Then W - S = (c1 a, s1 a, b) with (a, b) = Rot(theta2) (X, Y).
  const double horizontal = std::sqrt(x_sw.x() * x_sw.x() + x_sw.y() * x_sw.y());
  double theta1 = 0.0;
  double a = x_sw.x();  // stated choice theta1 = 0 when W is on the joint-1 axis
  if (horizontal <= singular_tolerance * length) {
    f.singular |= kArmAngleSingular;
  } else {
    theta1 = std::atan2(x_sw.y(), x_sw.x());
    a = horizontal;
  }
  const double big_x = g.d_ew * s4;
  const double big_y = g.d_se + g.d_ew * c4;
  const double theta2 = std::atan2(big_x * x_sw.z() - big_y * a, big_x * a + big_y * x_sw.z());
  const double c1 = std::cos(theta1), s1 = std::sin(theta1);
  const double c2 = std::cos(theta2), s2 = std::sin(theta2);
  f.r03_reference << c1 * c2, c1 * s2, -s1,  //
      s1 * c2, s1 * s2, c1,                  //
      s2, -c2, 0.0;
  const Eigen::Matrix3d k = skew(f.u);
  f.as = k * f.r03_reference;
  f.bs = -k * f.as;
  f.cs = f.u * (f.u.transpose() * f.r03_reference);
  return f;
}

LwrBaseSolution lwr_base_solution(const LwrPoseFrame& f, double psi_rad, const IkOptions& options) {
  LwrBaseSolution s{};
  s.singular = f.singular;
  const double sp = std::sin(psi_rad), cp = std::cos(psi_rad);
  const Eigen::Matrix3d r03 = sp * f.as + cp * f.bs + f.cs;
  // R03 = P(t1) M(t2) M(t3): its column 1 is -(column 2 of P M); pass it as column 2.
  Eigen::Matrix3d r03_view;
  r03_view << r03.col(0), r03.col(2), -r03.col(1);
  // The stated choice at a singularity: joint 3 (or 7) = options.singular_free_angle_rad.
  if (solve_pm(r03_view, options.singular_tolerance, options.singular_free_angle_rad + f.offset3,
               s.theta[0], s.theta[1], s.theta[2])) {
    s.singular |= kShoulderSingular;
  }
  s.theta[3] = f.theta4;
  const Eigen::Matrix3d r47 = (r03 * f.r34).transpose() * f.r;
  if (solve_pm(r47, options.singular_tolerance, options.singular_free_angle_rad + f.offset7,
               s.theta[4], s.theta[5], s.theta[6])) {
    s.singular |= kWristSingular;
  }
  return s;
}

Eigen::Matrix3d lwr_shoulder_rotation(double theta1, double theta2, double theta3) {
  const auto p = [](double t) {
    return Eigen::AngleAxisd(t, Eigen::Vector3d::UnitZ()) *
           Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX());
  };
  const auto m = [](double t) {
    return Eigen::AngleAxisd(t, Eigen::Vector3d::UnitZ()) *
           Eigen::AngleAxisd(-kPi / 2, Eigen::Vector3d::UnitX());
  };
  return (p(theta1) * m(theta2) * m(theta3)).toRotationMatrix();
}

void lwr_flip(const double base[7], int index, double out[7]) {
  for (int i = 0; i < 7; ++i) out[i] = base[i];
  if ((index & 4) != 0) {  // theta2 -> -theta2, theta1 + pi, theta3 + pi
    out[0] += kPi;
    out[1] = -out[1];
    out[2] += kPi;
  }
  if ((index & 2) != 0) {  // theta4 -> -theta4, theta3 + pi, theta5 + pi
    out[2] += kPi;
    out[3] = -out[3];
    out[4] += kPi;
  }
  if ((index & 1) != 0) {  // theta6 -> -theta6, theta5 + pi, theta7 + pi
    out[4] += kPi;
    out[5] = -out[5];
    out[6] += kPi;
  }
  for (int i = 0; i < 7; ++i) out[i] = wrap_angle(out[i]);
}

void lwr_flips(const double base[7], double out[8][7]) {
  const double t0[2] = {wrap_angle(base[0]), wrap_angle(base[0] + kPi)};
  const double t1[2] = {wrap_angle(base[1]), wrap_angle(-base[1])};
  const double t2[3] = {wrap_angle(base[2]), wrap_angle(base[2] + kPi),
                        wrap_angle((base[2] + kPi) + kPi)};
  const double t3[2] = {wrap_angle(base[3]), wrap_angle(-base[3])};
  const double t4[3] = {wrap_angle(base[4]), wrap_angle(base[4] + kPi),
                        wrap_angle((base[4] + kPi) + kPi)};
  const double t5[2] = {wrap_angle(base[5]), wrap_angle(-base[5])};
  const double t6[2] = {wrap_angle(base[6]), wrap_angle(base[6] + kPi)};
  for (int index = 0; index < 8; ++index) {
    const int shoulder = (index >> 2) & 1, elbow = (index >> 1) & 1, wrist = index & 1;
    out[index][0] = t0[shoulder];
    out[index][1] = t1[shoulder];
    out[index][2] = t2[shoulder + elbow];
    out[index][3] = t3[elbow];
    out[index][4] = t4[elbow + wrist];
    out[index][5] = t5[wrist];
    out[index][6] = t6[wrist];
  }
}

}  // namespace vrreg::kinematics::detail
