// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/multidirectional.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

// Union-find over target indices.
struct Groups {
  std::vector<std::size_t> parent;
  explicit Groups(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t root(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) {
    a = root(a);
    b = root(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

std::string approach_text(const std::vector<double>& approach_sign) {
  std::string text;
  for (const double s : approach_sign) text += s > 0.0 ? '+' : (s < 0.0 ? '-' : '0');
  return text;
}

MultidirectionalAccuracy multidirectional_accuracy(
    const ConstPoints3Ref& nominal_robot_m, const ConstPoints3Ref& unc_robot_m,
    const ConstPoints3Ref& cor_robot_m, const std::vector<std::vector<double>>& approach_sign,
    const std::vector<std::string>& names, const std::vector<std::optional<int>>& configs,
    const std::vector<bool>& included, double same_point_m) {
  const auto n = static_cast<std::size_t>(nominal_robot_m.cols());
  VRREG_THROW_UNLESS(
      static_cast<std::size_t>(unc_robot_m.cols()) == n &&
          static_cast<std::size_t>(cor_robot_m.cols()) == n && approach_sign.size() == n &&
          (names.empty() || names.size() == n) && (configs.empty() || configs.size() == n) &&
          (included.empty() || included.size() == n),
      "multi-directional accuracy: " << n << " nominal positions, " << unc_robot_m.cols()
                                     << " uncorrected, " << cor_robot_m.cols() << " corrected, "
                                     << approach_sign.size() << " directions, " << names.size()
                                     << " names, " << included.size() << " flags");
  VRREG_THROW_UNLESS(std::isfinite(same_point_m) && same_point_m >= 0.0,
                     "multi-directional accuracy: same_point_m " << same_point_m);
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < n; ++i) {
    if ((included.empty() || included[i]) && !approach_sign[i].empty()) used.push_back(i);
  }
  // Points: in one configuration, the same name, or nominal positions within same_point_m (a
  // sweep along x).
  const auto config_of = [&](std::size_t i) {
    return configs.empty() ? std::optional<int>() : configs[i];
  };
  Groups groups(n);
  std::map<std::pair<std::string, std::optional<int>>, std::size_t> first_of_name;
  for (const std::size_t i : used) {
    if (names.empty() || names[i].empty()) continue;
    const auto [it, added] = first_of_name.try_emplace({names[i], config_of(i)}, i);
    if (!added) groups.join(it->second, i);
  }
  std::vector<std::size_t> by_x = used;
  std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) {
    return nominal_robot_m(0, static_cast<Eigen::Index>(a)) <
           nominal_robot_m(0, static_cast<Eigen::Index>(b));
  });
  for (std::size_t a = 0; a < by_x.size(); ++a) {
    const auto ia = static_cast<Eigen::Index>(by_x[a]);
    for (std::size_t b = a + 1; b < by_x.size(); ++b) {
      const auto ib = static_cast<Eigen::Index>(by_x[b]);
      if (nominal_robot_m(0, ib) - nominal_robot_m(0, ia) > same_point_m) break;
      if ((nominal_robot_m.col(ib) - nominal_robot_m.col(ia)).norm() <= same_point_m &&
          config_of(by_x[a]) == config_of(by_x[b])) {
        groups.join(by_x[a], by_x[b]);
      }
    }
  }
  // Per point, its directions in order of first appearance, with their targets.
  std::map<std::size_t, std::vector<std::pair<std::vector<double>, std::vector<std::size_t>>>>
      points;
  std::vector<std::size_t> point_order;
  for (const std::size_t i : used) {
    const std::size_t r = groups.root(i);
    auto [it, added] = points.try_emplace(r);
    if (added) point_order.push_back(r);
    auto& directions = it->second;
    auto d = std::find_if(directions.begin(), directions.end(),
                          [&](const auto& entry) { return entry.first == approach_sign[i]; });
    if (d == directions.end()) {
      directions.emplace_back(approach_sign[i], std::vector<std::size_t>{});
      d = std::prev(directions.end());
    }
    d->second.push_back(i);
  }
  MultidirectionalAccuracy out;
  std::vector<double> unc_spread, cor_spread;
  std::vector<Eigen::Vector2d> sums;  // per direction: squared errors, uncorrected and corrected
  for (const std::size_t r : point_order) {
    const auto& directions = points[r];
    if (directions.size() < 2) continue;
    ++out.n_points;
    out.point_names.push_back(names.empty() ? "#" + std::to_string(r + 1) : names[r]);
    // Mean errors (reached minus nominal) per direction: the barycentres, one nominal position.
    std::vector<Eigen::Vector3d> unc_mean, cor_mean;
    for (const auto& [sign_key, targets] : directions) {
      // A named copy: clang before 16 cannot capture a structured binding in a lambda.
      const auto& sign = sign_key;
      Eigen::Vector3d u = Eigen::Vector3d::Zero(), c = Eigen::Vector3d::Zero();
      auto g = std::find_if(out.directions.begin(), out.directions.end(),
                            [&sign](const DirectionAccuracy& a) { return a.approach_sign == sign; });
      if (g == out.directions.end()) {
        out.directions.push_back({sign, 0, 0.0, 0.0});
        sums.emplace_back(Eigen::Vector2d::Zero());
        g = std::prev(out.directions.end());
      }
      const auto k = static_cast<std::size_t>(g - out.directions.begin());
      for (const std::size_t i : targets) {
        const auto col = static_cast<Eigen::Index>(i);
        const Eigen::Vector3d eu = unc_robot_m.col(col) - nominal_robot_m.col(col);
        const Eigen::Vector3d ec = cor_robot_m.col(col) - nominal_robot_m.col(col);
        u += eu;
        c += ec;
        sums[k] += Eigen::Vector2d(eu.squaredNorm(), ec.squaredNorm());
        ++g->n_targets;
      }
      unc_mean.push_back(u / static_cast<double>(targets.size()));
      cor_mean.push_back(c / static_cast<double>(targets.size()));
    }
    double du = 0.0, dc = 0.0;
    for (std::size_t a = 0; a < unc_mean.size(); ++a) {
      for (std::size_t b = a + 1; b < unc_mean.size(); ++b) {
        du = std::max(du, (unc_mean[a] - unc_mean[b]).norm());
        dc = std::max(dc, (cor_mean[a] - cor_mean[b]).norm());
      }
    }
    unc_spread.push_back(du);
    cor_spread.push_back(dc);
  }
  for (std::size_t k = 0; k < out.directions.size(); ++k) {
    const double m = static_cast<double>(out.directions[k].n_targets);
    out.directions[k].unc_rms_t_m = std::sqrt(sums[k](0) / m);
    out.directions[k].cor_rms_t_m = std::sqrt(sums[k](1) / m);
  }
  out.unc_spread_m = Eigen::Map<const Eigen::VectorXd>(
      unc_spread.data(), static_cast<Eigen::Index>(unc_spread.size()));
  out.cor_spread_m = Eigen::Map<const Eigen::VectorXd>(
      cor_spread.data(), static_cast<Eigen::Index>(cor_spread.size()));
  if (out.n_points > 0) {
    out.unc_max_spread_m = out.unc_spread_m.maxCoeff();
    out.unc_mean_spread_m = out.unc_spread_m.mean();
    out.cor_max_spread_m = out.cor_spread_m.maxCoeff();
    out.cor_mean_spread_m = out.cor_spread_m.mean();
  }
  return out;
}

}  // namespace vrreg
