// SPDX-License-Identifier: Apache-2.0
// Closed-form UR inverse kinematics (after Hawkins 2013, re-derived for this code):
//   wrist centre o5 = p - d6 z6; z1 . o5 = d4 fixes q1 (2 branches);
//   z1 in the flange frame is (s5 c6, -s5 s6, c5), which fixes q5 (2 branches) and q6;
//   o4 = o5 + d5 (s6 x6 + c6 y6) and x4 give the planar 3R problem in frame 1: q3 by the law of
//   cosines (2 branches), then q2 and q4 = q234 - q2 - q3.
// Later joints are computed from the earlier ones as computed, so rounding does not accumulate.
#include "vrreg/kinematics/ur_ik.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "length_text.hpp"
#include "limits_fit.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/pose.hpp"

namespace vrreg::kinematics {
namespace {

using units::kPi;

struct UrGeometry {
  double d1, a2, a3, d4, d5, d6;
  double offset[6];
};

UrGeometry ur_geometry(const SerialChain& chain, const char* what) {
  VRREG_THROW_UNLESS(chain.family() == ChainFamily::kUr,
                     what << ": robot '" << chain.name()
                          << "' does not have the UR structure (6 joints, alpha = [90, 0, 0, 90, "
                             "-90, 0] deg, a1 = a4 = a5 = a6 = 0); its family is "
                          << to_string(chain.family()));
  UrGeometry g{};
  g.d1 = chain.row(0).d_m;
  g.a2 = chain.row(1).a_m;
  g.a3 = chain.row(2).a_m;
  g.d4 = chain.row(1).d_m + chain.row(2).d_m + chain.row(3).d_m;  // parallel axes: offsets add
  g.d5 = chain.row(4).d_m;
  g.d6 = chain.row(5).d_m;
  for (int i = 0; i < 6; ++i) g.offset[i] = chain.row(i).theta_offset_rad;
  return g;
}

struct Branch {
  double theta[6];
  std::uint8_t singular;
  bool present;
};

// Elbow (frame-2 origin) above the line from the shoulder to o3 = (px, py) in the arm plane of
// frame 1 (y1 up): px * (-a2 a3 sin q3) > 0; px = 0 counts as positive (a measure-zero tie).
bool elbow_up(double px, double cross) { return (px >= 0.0 ? cross : -cross) > 0.0; }

using detail::mm;

// Below this |sin q5| a refusal says that the orientation's rounding may be what put the wrist
// out of reach (q6 = atan2 of two numbers of this size).
constexpr double kNearSingularWrist = 1e-6;

// At the shoulder singularity q1 is known to about sqrt(rounding) only (the wrist centre's
// distance from the upper arm's plane, d4, changes to second order in q1), and that noise in z1
// would hide a singular wrist (z1 = +-z6): its q6 would come from noise instead of the free angle.
// When a q1 with z1 = +-z6 satisfies z1 . o5 = d4 as well as the computed one does, take it.
void snap_to_singular_wrist(const Eigen::Vector3d& o5, const Eigen::Vector3d& z6, double d4,
                            double tolerance, double& theta1, double& c1, double& s1) {
  const double horizontal = std::hypot(z6.x(), z6.y());
  if (!(horizontal > 0.0) || std::abs(z6.z()) > tolerance * horizontal) return;
  const double side = s1 * z6.x() - c1 * z6.y() >= 0.0 ? 1.0 : -1.0;  // sign of z1 . z6
  const double s1_wrist = side * z6.x() / horizontal;
  const double c1_wrist = -side * z6.y() / horizontal;
  const double radius = std::hypot(o5.x(), o5.y());
  const double allowed = 16.0 * std::numeric_limits<double>::epsilon() * std::max(radius, 1.0);
  const double miss = std::abs(s1_wrist * o5.x() - c1_wrist * o5.y() - d4);
  if (miss > std::max(allowed, std::abs(s1 * o5.x() - c1 * o5.y() - d4))) return;
  c1 = c1_wrist;
  s1 = s1_wrist;
  theta1 = std::atan2(s1, c1);
}

// The wrist-singular q6 (sin q5 ~ 0). There the frame-4 origin o4 = o5 + d5 (s6 x6 + c6 y6)
// moves on a circle of radius d5 about the wrist centre in the arm plane as q6 turns, so q6
// decides whether the planar arm reaches o4: |o4 - S|^2 = |C|^2 + d5^2 + 2 d5 |C| cos(q6 - gamma),
// with C the wrist centre relative to the shoulder S in the arm plane and gamma its angle in the
// (y6, x6) basis. Returns theta6 = `theta6_wanted` when that reach is within [reach_min,
// reach_max], else the feasible theta6 nearest it; empty when no theta6 is feasible, with the
// range of |o4 - S| over the circle in `reach_range`.
std::optional<double> feasible_singular_theta6(double theta6_wanted, const Eigen::Vector2d& centre,
                                               const Eigen::Vector2d& u, const Eigen::Vector2d& v,
                                               double d5, double reach_min, double reach_max,
                                               double tolerance_m, double reach_range[2]) {
  const double c_norm = centre.norm();
  const double lever = 2.0 * std::abs(d5) * c_norm;
  reach_range[0] = std::abs(c_norm - std::abs(d5));
  reach_range[1] = c_norm + std::abs(d5);
  if (reach_range[1] < reach_min - tolerance_m || reach_range[0] > reach_max + tolerance_m) {
    return std::nullopt;
  }
  if (lever == 0.0) return theta6_wanted;  // o4 does not move with q6: reach checked above
  // cos(q6 - gamma) within [lo, hi] keeps |o4 - S| within the reach.
  const double base = c_norm * c_norm + d5 * d5;
  const double lo = (reach_min * reach_min - base) / lever;
  const double hi = (reach_max * reach_max - base) / lever;
  // d5 (s6 u + c6 v) . C = d5 |C| cos(q6 - gamma): gamma from the coordinates of d5 C in (u, v).
  const double gamma = std::atan2(d5 * centre.dot(u), d5 * centre.dot(v));
  const double smallest = std::acos(std::clamp(hi, -1.0, 1.0));  // least |q6 - gamma| allowed
  const double largest = std::acos(std::clamp(lo, -1.0, 1.0));   // most |q6 - gamma| allowed
  const double delta = wrap_angle(theta6_wanted - gamma);
  const double side = delta < 0.0 ? -1.0 : 1.0;
  if (std::abs(delta) < smallest) return gamma + side * smallest;
  if (std::abs(delta) > largest) return gamma + side * largest;
  return theta6_wanted;
}

}  // namespace

IkResult ur_inverse_kinematics(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                               const IkOptions& options) {
  const UrGeometry g = ur_geometry(chain, "UR inverse kinematics");
  options.validate();
  check_pose(T_base_tcp, "UR inverse kinematics: target pose");
  const Eigen::Isometry3d t = chain.dh0_flange_from_base_tcp(T_base_tcp);
  const Eigen::Matrix3d& r = t.linear();
  const Eigen::Vector3d x6 = r.col(0), y6 = r.col(1), z6 = r.col(2);
  const Eigen::Vector3d p = t.translation();
  const double tol = options.singular_tolerance;

  IkResult result;
  Branch branches[8] = {};  // by configuration index
  int n_branches = 0;
  std::uint8_t pose_flags = kNoSingularity;

  // q1: the wrist centre lies at distance d4 from the vertical plane of the upper arm.
  const Eigen::Vector3d o5 = p - g.d6 * z6;
  // No configuration puts the wrist centre farther from the shoulder than the planar arm's reach
  // beside the d4 offset, plus d5. Refused here, before the squares below overflow for a far
  // target and turn into NaN joints.
  const double reach_bound = std::hypot(std::abs(g.a2) + std::abs(g.a3), g.d4) + std::abs(g.d5);
  const double from_shoulder = std::hypot(o5.x(), o5.y(), o5.z() - g.d1);
  if (!(from_shoulder <= reach_bound + options.reach_tolerance_m)) {
    result.message = "the wrist centre is " + mm(from_shoulder) +
                     " from the shoulder, beyond the arm's reach (at most " + mm(reach_bound) +
                     " in any configuration)";
    return result;
  }
  const double r2 = o5.x() * o5.x() + o5.y() * o5.y();
  const double radius = std::sqrt(r2);
  if (radius < std::abs(g.d4) - options.reach_tolerance_m) {
    result.message = "the wrist centre is " + mm(radius) +
                     " from the joint-1 axis, closer than d4 = " + mm(std::abs(g.d4)) +
                     ": inside the cylinder no configuration reaches";
    return result;
  }
  const double h_abs = std::sqrt(std::max(r2 - g.d4 * g.d4, 0.0));  // reach in the arm plane
  // Found through a square root (like q3 below): test cos^2 of the angle, not |sin| (see
  // IkOptions).
  const bool shoulder_singular = h_abs * h_abs <= tol * r2;
  if (shoulder_singular) pose_flags |= kShoulderSingular;
  const double cos_phi = radius > 0 ? o5.x() / radius : 1.0;
  const double sin_phi = radius > 0 ? o5.y() / radius : 0.0;
  const double sin_alpha = radius > 0 ? std::clamp(g.d4 / radius, -1.0, 1.0) : 1.0;
  const double cos_alpha = radius > 0 ? h_abs / radius : 0.0;
  const double phi = std::atan2(o5.y(), o5.x());
  const double alpha = std::atan2(sin_alpha, cos_alpha);
  const double reach_max = std::abs(g.a2) + std::abs(g.a3);
  const double reach_min = std::abs(std::abs(g.a2) - std::abs(g.a3));
  double worst_reach = -1.0;
  double nearest_singular_s5 = 1.0;    // |sin q5| of the failed branches
  std::string singular_reach_message;  // why a wrist-singular shoulder branch has no solution

  for (int shoulder = 0; shoulder < (shoulder_singular ? 1 : 2); ++shoulder) {
    // shoulder 0: h = +h_abs (q1 = phi + alpha); 1: h = -h_abs (q1 = phi + pi - alpha).
    const double h_sign = shoulder == 0 ? 1.0 : -1.0;
    double theta1 = shoulder == 0 ? phi + alpha : phi + kPi - alpha;
    // cos/sin of q1 without trigonometry: rotate (cos phi, sin phi) by alpha or pi - alpha.
    const double ca = h_sign * cos_alpha;
    double c1 = cos_phi * ca - sin_phi * sin_alpha;
    double s1 = sin_phi * ca + cos_phi * sin_alpha;
    if (shoulder_singular) snap_to_singular_wrist(o5, z6, g.d4, tol, theta1, c1, s1);
    const Eigen::Vector3d z1(s1, -c1, 0.0);
    const double zx = z1.dot(x6), zy = z1.dot(y6), c5 = z1.dot(z6);
    const double s5_abs = std::sqrt(zx * zx + zy * zy);
    const bool wrist_singular = s5_abs <= tol;
    if (wrist_singular) pose_flags |= kWristSingular;

    const double theta5_abs = std::atan2(s5_abs, c5);
    double theta6_noflip = options.singular_free_angle_rad + g.offset[5];
    double s6_noflip = 0.0, c6_noflip = 1.0;
    if (wrist_singular) {
      const Eigen::Vector2d centre(c1 * o5.x() + s1 * o5.y(), o5.z() - g.d1);
      const Eigen::Vector2d u(c1 * x6.x() + s1 * x6.y(), x6.z());
      const Eigen::Vector2d v(c1 * y6.x() + s1 * y6.y(), y6.z());
      double range[2];
      const std::optional<double> theta6 =
          feasible_singular_theta6(theta6_noflip, centre, u, v, g.d5, reach_min, reach_max,
                                   options.reach_tolerance_m, range);
      if (!theta6) {
        singular_reach_message = "at the wrist singularity (sin q5 = 0) the wrist (frame 4 "
                                 "origin) stays " +
                                 mm(range[0]) + " to " + mm(range[1]) +
                                 " from the shoulder whatever q6, outside the arm's reach [" +
                                 mm(reach_min) + ", " + mm(reach_max) + "]";
        continue;
      }
      theta6_noflip = *theta6;
      s6_noflip = std::sin(theta6_noflip);
      c6_noflip = std::cos(theta6_noflip);
    } else {
      s6_noflip = -zy / s5_abs;
      c6_noflip = zx / s5_abs;
      theta6_noflip = std::atan2(-zy, zx);
    }

    for (int wrist = 0; wrist < (wrist_singular ? 1 : 2); ++wrist) {
      // The flipped wrist: q5 -> -q5, and z1 in the flange frame fixes q6 -> q6 + pi.
      const double flip = wrist == 0 ? 1.0 : -1.0;
      const double s5 = flip * s5_abs;
      const double theta5 = flip * theta5_abs;
      const double s6 = flip * s6_noflip, c6 = flip * c6_noflip;
      const double theta6 = wrist == 0 ? theta6_noflip : theta6_noflip + kPi;
      // Frame 4: origin and x axis, then the planar problem in frame 1 (x1 horizontal, y1 up).
      const Eigen::Vector3d o4 = o5 + g.d5 * (s6 * x6 + c6 * y6);
      const Eigen::Vector3d x4 = c5 * c6 * x6 - c5 * s6 * y6 - s5 * z6;
      const double px = c1 * o4.x() + s1 * o4.y();
      const double py = o4.z() - g.d1;
      const double theta234 = std::atan2(x4.z(), c1 * x4.x() + s1 * x4.y());
      const double reach = std::sqrt(px * px + py * py);
      if (reach > reach_max + options.reach_tolerance_m ||
          reach < reach_min - options.reach_tolerance_m) {
        worst_reach = reach;
        nearest_singular_s5 = std::min(nearest_singular_s5, s5_abs);
        continue;
      }
      const double c3 = std::clamp(
          (px * px + py * py - g.a2 * g.a2 - g.a3 * g.a3) / (2.0 * g.a2 * g.a3), -1.0, 1.0);
      const double s3_abs = std::sqrt(std::max(0.0, 1.0 - c3 * c3));
      const bool elbow_singular = 1.0 - std::abs(c3) <= tol;
      if (elbow_singular) pose_flags |= kElbowSingular;
      // (px, py) = Rot(q2) (a2 + a3 c3, a3 s3): q2 = angle(px, py) -+ angle(a2 + a3 c3, a3 |s3|).
      const double theta3_abs = std::atan2(s3_abs, c3);
      const double angle_p = std::atan2(py, px);
      const double angle_b = std::atan2(g.a3 * s3_abs, g.a2 + g.a3 * c3);

      for (int elbow = 0; elbow < (elbow_singular ? 1 : 2); ++elbow) {
        const double sign3 = elbow == 0 ? 1.0 : -1.0;
        const double theta3 = sign3 * theta3_abs;
        const double theta2 = angle_p - sign3 * angle_b;
        const double theta4 = theta234 - theta2 - theta3;
        const int index = (h_sign * g.d4 > 0.0 ? 4 : 0) |
                          (elbow_up(px, -g.a2 * g.a3 * sign3 * s3_abs) ? 0 : 2) |
                          (s5 < 0.0 ? 1 : 0);
        Branch& b = branches[index];
        assert(!b.present);
        b.present = true;
        ++n_branches;
        b.theta[0] = theta1;
        b.theta[1] = theta2;
        b.theta[2] = theta3;
        b.theta[3] = theta4;
        b.theta[4] = theta5;
        b.theta[5] = theta6;
        b.singular = static_cast<std::uint8_t>((shoulder_singular ? kShoulderSingular : 0) |
                                               (wrist_singular ? kWristSingular : 0) |
                                               (elbow_singular ? kElbowSingular : 0));
      }
    }
  }
  result.singular = pose_flags;
  if (n_branches == 0) {
    result.message = worst_reach >= 0.0 ? "the wrist (frame 4 origin) is " + mm(worst_reach) +
                                              " from the shoulder, outside the arm's reach [" +
                                              mm(reach_min) + ", " + mm(reach_max) + "]"
                                        : singular_reach_message;
    if (worst_reach >= 0.0 && nearest_singular_s5 <= kNearSingularWrist) {
      result.message += "; the wrist is nearly singular (|sin q5| = " +
                        format_general(nearest_singular_s5, 2) +
                        "), where q6, and with it the wrist, follows the last digits of the "
                        "orientation: give it to more digits";
    }
    return result;
  }

  result.solutions.reserve(static_cast<std::size_t>(n_branches));
  for (int index = 0; index < 8; ++index) {
    const Branch& b = branches[index];
    if (!b.present) continue;
    // Default-initialised, then appended: emplace_back() would value-initialise it (zeroing all
    // of its fixed-size joint storage with a `rep stos`, a sixth of the call).
    IkSolution solution;
    JointVector& q = solution.q_rad;
    q.resize(6);
    bool inside = true;
    for (int i = 0; i < 6; ++i) {
      q(i) = wrap_angle(b.theta[i] - g.offset[i]);
      if (options.apply_joint_limits && inside) {
        inside = detail::shift_joint(q(i), chain.limit(i), 0.0);
      }
    }
    if (!inside) {
      ++result.n_outside_limits;
      continue;
    }
    solution.config = ConfigurationLabel(ArmKind::kUr, index);
    solution.singular = b.singular;
    result.solutions.push_back(solution);
  }
  if (result.solutions.empty()) {
    result.status = IkStatus::kOutsideLimits;
    result.message = "all " + std::to_string(n_branches) + " solutions violate the joint limits";
  } else {
    result.status = IkStatus::kOk;
  }
  return result;
}

IkResult ur_inverse_kinematics_nearest(const SerialChain& chain,
                                       const Eigen::Isometry3d& T_base_tcp,
                                       const JointRef& q_current_rad, JointNorm norm,
                                       const IkOptions& options) {
  chain.check_joints(q_current_rad, "UR nearest IK: current joints");
  IkOptions all_options = options;
  all_options.apply_joint_limits = false;  // limits are applied to the shifted joints
  all_options.singular_free_angle_rad = q_current_rad(5);
  return nearest_solution(chain, ur_inverse_kinematics(chain, T_base_tcp, all_options),
                          q_current_rad, norm);
}

ConfigurationLabel ur_configuration(const SerialChain& chain, const JointRef& q_rad) {
  const UrGeometry g = ur_geometry(chain, "UR configuration");
  chain.check_joints(q_rad, "UR configuration");
  double theta[6];
  for (int i = 0; i < 6; ++i) theta[i] = q_rad(i) + g.offset[i];
  const double t23 = theta[1] + theta[2];
  const double t234 = t23 + theta[3];
  // Frame-3 origin in the arm plane of frame 1 (x1 horizontal, y1 up), relative to the shoulder.
  const double px = g.a2 * std::cos(theta[1]) + g.a3 * std::cos(t23);
  const double h = px + g.d5 * std::sin(t234);  // reach of the wrist centre along x1
  // Elbow (a2 (c2, s2)) above the line to (px, py): px * cross > 0, cross = -a2 a3 sin q3.
  return ConfigurationLabel::ur(!(h * g.d4 > 0.0), elbow_up(px, -g.a2 * g.a3 * std::sin(theta[2])),
                                std::sin(theta[4]) < 0.0);
}

}  // namespace vrreg::kinematics
