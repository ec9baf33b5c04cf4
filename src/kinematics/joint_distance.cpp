// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/joint_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include "limits_fit.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg::kinematics {
namespace {

void check_sizes(const JointRef& a, const JointRef& b) {
  VRREG_THROW_UNLESS(a.size() == b.size(), "joint distance: joint vectors differ in size ("
                                               << a.size() << " vs " << b.size() << ")");
}

std::optional<JointVector> shift_towards(const SerialChain& chain, const JointRef& q_rad,
                                         const JointRef* reference) {
  chain.check_joints(q_rad, "shift into limits");
  JointVector out(chain.n_joints());
  for (int i = 0; i < chain.n_joints(); ++i) {
    const JointLimits& l = chain.limit(i);
    const double target = reference != nullptr ? (*reference)(i) : 0.0;
    double v = q_rad(i);
    if (!chain.wraps(i)) {  // a slide (or a turn its rows do not repeat) has no turns to shift by
      if (!(v >= l.lower_rad && v <= l.upper_rad)) return std::nullopt;
    } else if (!detail::shift_joint(v, l, target)) {
      return std::nullopt;
    }
    out(i) = v;
  }
  return out;
}

}  // namespace

const char* to_string(JointNorm norm) { return norm == JointNorm::kL2 ? "l2" : "linf"; }

JointKinds::JointKinds(const SerialChain& chain)
    : prismatic_(static_cast<std::size_t>(chain.n_joints())) {
  for (int i = 0; i < chain.n_joints(); ++i) {
    prismatic_[static_cast<std::size_t>(i)] = !chain.wraps(i);
  }
}

double JointKinds::difference(Eigen::Index i, double a, double b) const {
  const auto k = static_cast<std::size_t>(i);
  return k < prismatic_.size() && prismatic_[k] ? a - b : wrap_angle(a - b);
}

double joint_distance_l2(const JointRef& a_rad, const JointRef& b_rad, const JointKinds& kinds) {
  check_sizes(a_rad, b_rad);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < a_rad.size(); ++i) {
    const double d = kinds.difference(i, a_rad(i), b_rad(i));
    sum += d * d;
  }
  return std::sqrt(sum);
}

double joint_distance_linf(const JointRef& a_rad, const JointRef& b_rad, const JointKinds& kinds) {
  check_sizes(a_rad, b_rad);
  double worst = 0.0;
  for (Eigen::Index i = 0; i < a_rad.size(); ++i) {
    worst = std::max(worst, std::abs(kinds.difference(i, a_rad(i), b_rad(i))));
  }
  return worst;
}

double joint_distance(const JointRef& a_rad, const JointRef& b_rad, JointNorm norm,
                      const JointKinds& kinds) {
  return norm == JointNorm::kL2 ? joint_distance_l2(a_rad, b_rad, kinds)
                                : joint_distance_linf(a_rad, b_rad, kinds);
}

std::vector<int> order_by_distance(const Eigen::Ref<const Eigen::MatrixXd>& candidates_rad,
                                   const JointRef& reference_rad, JointNorm norm,
                                   const JointKinds& kinds) {
  VRREG_THROW_UNLESS(candidates_rad.cols() == 0 || candidates_rad.rows() == reference_rad.size(),
                     "joint distance: candidates have " << candidates_rad.rows()
                                                        << " joints, the reference "
                                                        << reference_rad.size());
  const auto n = static_cast<std::size_t>(candidates_rad.cols());
  std::vector<double> distance(n);
  for (std::size_t j = 0; j < n; ++j) {
    distance[j] = joint_distance(candidates_rad.col(static_cast<Eigen::Index>(j)), reference_rad,
                                 norm, kinds);
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return distance[static_cast<std::size_t>(a)] < distance[static_cast<std::size_t>(b)];
  });
  return order;
}

std::optional<int> nearest_configuration(const Eigen::Ref<const Eigen::MatrixXd>& candidates_rad,
                                         const JointRef& reference_rad, JointNorm norm,
                                         const JointKinds& kinds) {
  const std::vector<int> order = order_by_distance(candidates_rad, reference_rad, norm, kinds);
  if (order.empty()) return std::nullopt;
  return order.front();
}

std::optional<JointVector> shift_nearest(const SerialChain& chain, const JointRef& q_rad,
                                         const JointRef& reference_rad) {
  chain.check_joints(reference_rad, "shift towards reference");
  return shift_towards(chain, q_rad, &reference_rad);
}

std::optional<JointVector> shift_into_limits(const SerialChain& chain, const JointRef& q_rad) {
  return shift_towards(chain, q_rad, nullptr);
}

}  // namespace vrreg::kinematics
