// SPDX-License-Identifier: Apache-2.0
#include "joint_gaps.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "method_support.hpp"
#include "vrreg/kinematics/marker_partials.hpp"

namespace vrreg::detail {
namespace {

// Joint values closer than this are one value (a file's commanded joints repeat to ~1e-9) [rad; m].
constexpr double kMergeTolerance = 1e-6;
// A gap is wide when the marker moves more than this many layout spacings across it: a lattice's
// own joint steps move it about one (the contract cube's base joint: 27 mm at 27 mm spacing),
// a rail's carriage positions 0.3 m apart fifteen.
constexpr double kWideGapSpacings = 2.0;
// In a wide gap nothing measured, a point this many layout spacings of marker motion from a
// measured value is outside the support (as a quarter spacing beyond the fiducials' box is).
constexpr double kNearMeasuredSpacings = 0.25;
// Values held out per joint to measure its gaps: each costs a refit.
constexpr std::size_t kMaxHeldOutValues = 8;
// Fiducials whose joints' levers are sampled (evenly), for a median.
constexpr Eigen::Index kLeverSamples = 200;

}  // namespace

JointGaps::JointGaps(const CorrectorData& data, const Eigen::Vector3d& p_flange_marker_m,
                     Eigen::VectorXd gap_error_m) {
  const auto n_joints = static_cast<int>(data.joints_rad.rows());
  const Eigen::Index n = data.size();
  if (!data.robot || n_joints == 0 || n < 2) return;
  values_.resize(static_cast<std::size_t>(n_joints));
  lever_m_.resize(n_joints);
  const Eigen::Index step = std::max<Eigen::Index>(1, n / kLeverSamples);
  std::vector<std::vector<double>> levers(static_cast<std::size_t>(n_joints));
  for (Eigen::Index j = 0; j < n; j += step) {
    const kinematics::MarkerPartials p =
        kinematics::marker_partials(*data.robot, data.joints_rad.col(j), p_flange_marker_m);
    for (int i = 0; i < n_joints; ++i) levers[static_cast<std::size_t>(i)].push_back(p.d_joint.col(i).norm());
  }
  for (int i = 0; i < n_joints; ++i) {
    std::vector<double>& l = levers[static_cast<std::size_t>(i)];
    std::nth_element(l.begin(), l.begin() + static_cast<std::ptrdiff_t>(l.size() / 2), l.end());
    lever_m_(i) = l[l.size() / 2];
    std::vector<double> v;
    v.reserve(static_cast<std::size_t>(n));
    for (Eigen::Index j = 0; j < n; ++j) v.push_back(data.joints_rad(i, j));
    std::sort(v.begin(), v.end());
    std::vector<double>& distinct = values_[static_cast<std::size_t>(i)];
    for (const double x : v) {
      if (distinct.empty() || x - distinct.back() > kMergeTolerance) distinct.push_back(x);
    }
  }
  spacing_m_ = layout_spacing_m(data.fiducials_robot_m);
  if (gap_error_m.size() == n_joints) {
    gap_error_m_ = std::move(gap_error_m);
    return;
  }
  gap_error_m_ = Eigen::VectorXd::Constant(n_joints, kNoWideGap);
  for (int i = 0; i < n_joints; ++i) {
    const std::vector<double>& v = values_[static_cast<std::size_t>(i)];
    for (std::size_t k = 1; k < v.size(); ++k) {
      if (wide(i, v[k] - v[k - 1])) gap_error_m_(i) = kUnmeasured;
    }
  }
}

bool JointGaps::wide(int joint, double width) const {
  return width * lever_m_(joint) > kWideGapSpacings * spacing_m_;
}

std::vector<double> JointGaps::interior_values(int joint) const {
  const std::vector<double>& v = values_[static_cast<std::size_t>(joint)];
  std::vector<double> next_to_gap;
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    if (wide(joint, v[k] - v[k - 1]) || wide(joint, v[k + 1] - v[k])) next_to_gap.push_back(v[k]);
  }
  if (next_to_gap.size() <= kMaxHeldOutValues) return next_to_gap;
  std::vector<double> out;
  for (std::size_t k = 0; k < kMaxHeldOutValues; ++k)
    out.push_back(next_to_gap[k * next_to_gap.size() / kMaxHeldOutValues]);
  return out;
}

std::vector<Eigen::Index> JointGaps::at_value(const Eigen::MatrixXd& q_rad, int joint,
                                              double value) const {
  std::vector<Eigen::Index> out;
  for (Eigen::Index j = 0; j < q_rad.cols(); ++j) {
    if (std::abs(q_rad(joint, j) - value) <= kMergeTolerance) out.push_back(j);
  }
  return out;
}

void JointGaps::set_error(int joint, double error_m) { gap_error_m_(joint) = error_m; }

bool JointGaps::judges() const {
  for (Eigen::Index i = 0; i < gap_error_m_.size(); ++i) {
    if (gap_error_m_(i) != kNoWideGap) return true;
  }
  return false;
}

JointGaps::Answer JointGaps::at(const kinematics::JointRef& q_rad) const {
  Answer out;
  double sum_sq_m2 = 0.0;
  for (Eigen::Index i = 0; i < gap_error_m_.size(); ++i) {
    const double error_m = gap_error_m_(i);
    if (error_m == kNoWideGap || i >= q_rad.size()) continue;
    const std::vector<double>& v = values_[static_cast<std::size_t>(i)];
    const double q = q_rad(i);
    const auto above = std::upper_bound(v.begin(), v.end(), q);
    if (above == v.begin() || above == v.end()) continue;  // at or beyond the range's ends
    const double a = *(above - 1);
    const double b = *above;
    if (!wide(static_cast<int>(i), b - a)) continue;
    const double d = std::min(q - a, b - q);
    if (error_m >= 0.0) {
      // A ripple shorter than twice the gap is as unknown a spacing from a measured value as
      // halfway: the whole error from one spacing on.
      const double share = std::min(1.0, d * lever_m_(i) / spacing_m_);
      sum_sq_m2 += error_m * error_m * share * share;
    } else if (d * lever_m_(i) > kNearMeasuredSpacings * spacing_m_) {
      out.unmeasured_m = std::max(out.unmeasured_m, d * lever_m_(i));
    }
  }
  out.sd_m = std::sqrt(sum_sq_m2);
  return out;
}

}  // namespace vrreg::detail
