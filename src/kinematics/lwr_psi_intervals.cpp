// SPDX-License-Identifier: Apache-2.0
// Feasible arm angles: each joint of the base configuration is theta = atan2(N(psi), D(psi)) or
// theta = acos(C(psi)) with N, D, C of the form a sin(psi) + b cos(psi) + c (entries of R03(psi)
// and R47(psi)). A joint meets a limit value beta where N cos(beta) - D sin(beta) = 0 (tangent
// type; covers the +pi flips of the other configurations too) or C = cos(beta) (cosine type);
// theta2 or theta6 crosses 0 (a jump of theta1/3/5/7 by pi) where C = +-1. Between consecutive
// roots every configuration is either feasible or not, which the IK at the midpoint decides.
#include "vrreg/kinematics/lwr_psi_intervals.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "limits_fit.hpp"
#include "lwr_solver.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/pose.hpp"

namespace vrreg::kinematics {
namespace {

using units::kPi;

// An entry of R(psi) = A sin(psi) + B cos(psi) + C.
struct Harmonic {
  double a, b, c;
  Harmonic operator*(double k) const { return {a * k, b * k, c * k}; }
  Harmonic operator-(const Harmonic& o) const { return {a - o.a, b - o.b, c - o.c}; }
};

Harmonic entry(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b, const Eigen::Matrix3d& c, int i,
               int j) {
  return {a(i, j), b(i, j), c(i, j)};
}

// Roots psi in (-pi, pi] of h.a sin(psi) + h.b cos(psi) + h.c = 0.
void add_roots(const Harmonic& h, std::vector<double>& roots) {
  const double amplitude = std::hypot(h.a, h.b);
  if (amplitude < 1e-14) return;  // constant in psi
  const double ratio = -h.c / amplitude;
  if (std::abs(ratio) > 1.0) return;
  // a sin + b cos = amplitude cos(psi - phi), phi = atan2(a, b).
  const double phi = std::atan2(h.a, h.b);
  const double delta = std::acos(ratio);
  roots.push_back(wrap_angle(phi + delta));
  roots.push_back(wrap_angle(phi - delta));
}

void add_tangent_roots(const Harmonic& n, const Harmonic& d, const JointLimits& limits,
                       double offset, std::vector<double>& roots) {
  if (limits.upper_rad - limits.lower_rad >= 2.0 * kPi) return;
  for (double q : {limits.lower_rad, limits.upper_rad}) {
    const double beta = q + offset;
    add_roots(n * std::cos(beta) - d * std::sin(beta), roots);
  }
}

void add_cosine_roots(const Harmonic& c, const JointLimits& limits, double offset,
                      std::vector<double>& roots) {
  for (double value : {1.0, -1.0}) add_roots(c - Harmonic{0.0, 0.0, value}, roots);
  if (limits.upper_rad - limits.lower_rad >= 2.0 * kPi) return;
  for (double q : {limits.lower_rad, limits.upper_rad}) {
    add_roots(c - Harmonic{0.0, 0.0, std::cos(q + offset)}, roots);
  }
}

}  // namespace

PsiIntervalsResult lwr_feasible_psi(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                                    const IkOptions& options) {
  const detail::LwrGeometry g = detail::lwr_geometry(chain, "LWR feasible arm angles");
  options.validate();
  check_pose(T_base_tcp, "LWR feasible arm angles: target pose");
  const Eigen::Isometry3d t = chain.dh0_flange_from_base_tcp(T_base_tcp);
  const detail::LwrPoseFrame f = detail::lwr_pose_frame(
      g, t.linear(), t.translation(), options.singular_tolerance, options.reach_tolerance_m);
  PsiIntervalsResult result;
  if (!f.reachable) {
    result.message = f.message;
    return result;
  }
  result.singular = f.singular;

  // R47(psi) = R34^T R03(psi)^T R: the same harmonic form.
  const Eigen::Matrix3d aw = f.r34.transpose() * f.as.transpose() * f.r;
  const Eigen::Matrix3d bw = f.r34.transpose() * f.bs.transpose() * f.r;
  const Eigen::Matrix3d cw = f.r34.transpose() * f.cs.transpose() * f.r;
  std::vector<double> roots;
  roots.reserve(48);
  const auto s = [&](int i, int j) { return entry(f.as, f.bs, f.cs, i, j); };
  const auto w = [&](int i, int j) { return entry(aw, bw, cw, i, j); };
  // theta1 = atan2(r11, r01), theta2: cos = -r21, theta3 = atan2(-r22, r20) of R03;
  // theta5 = atan2(-r12, -r02), theta6: cos = r22, theta7 = atan2(-r21, r20) of R47.
  add_tangent_roots(s(1, 1), s(0, 1), chain.limit(0), g.offset[0], roots);
  add_cosine_roots(s(2, 1) * -1.0, chain.limit(1), g.offset[1], roots);
  add_tangent_roots(s(2, 2) * -1.0, s(2, 0), chain.limit(2), g.offset[2], roots);
  add_tangent_roots(w(1, 2) * -1.0, w(0, 2) * -1.0, chain.limit(4), g.offset[4], roots);
  add_cosine_roots(w(2, 2), chain.limit(5), g.offset[5], roots);
  add_tangent_roots(w(2, 1) * -1.0, w(2, 0), chain.limit(6), g.offset[6], roots);
  roots.push_back(-kPi);
  roots.push_back(kPi);
  std::sort(roots.begin(), roots.end());
  roots.erase(std::unique(roots.begin(), roots.end()), roots.end());

  IkOptions midpoint_options = options;
  midpoint_options.singular_tolerance = 0.0;  // all eight branches, even near a singularity
  bool any = false;
  for (std::size_t k = 0; k + 1 < roots.size(); ++k) {
    const double lo = roots[k], hi = roots[k + 1];
    const detail::LwrBaseSolution base =
        detail::lwr_base_solution(f, 0.5 * (lo + hi), midpoint_options);
    for (int index = 0; index < 8; ++index) {
      double theta[7];
      detail::lwr_flip(base.theta, index, theta);
      bool inside = true;
      for (int i = 0; i < 7 && inside; ++i) {
        double q = wrap_angle(theta[i] - g.offset[i]);
        inside = detail::shift_joint(q, chain.limit(i), 0.0);
      }
      if (!inside) continue;
      any = true;
      std::vector<PsiInterval>& list = result.intervals[static_cast<std::size_t>(index)];
      if (!list.empty() && list.back().upper_rad == lo) {
        list.back().upper_rad = hi;  // continues the previous interval
      } else {
        list.push_back({lo, hi});
      }
    }
  }
  if (any) {
    result.status = IkStatus::kOk;
  } else {
    result.status = IkStatus::kOutsideLimits;
    result.message = "no arm angle puts every joint within its limits";
  }
  return result;
}

}  // namespace vrreg::kinematics
