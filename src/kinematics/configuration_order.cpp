// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/configuration_order.hpp"

#include <algorithm>
#include <numeric>
#include <set>
#include <string>

#include "vrreg/core/check.hpp"

namespace vrreg::kinematics {
namespace {

void check_point(const PointConfigurations& point, std::size_t p, Eigen::Index n_joints) {
  VRREG_THROW_UNLESS(!point.labels.empty(), "Strategy 2: point " << p << " has no configuration");
  VRREG_THROW_UNLESS(point.q_rad.cols() == static_cast<Eigen::Index>(point.labels.size()),
                     "Strategy 2: point " << p << " has " << point.labels.size() << " labels but "
                                          << point.q_rad.cols() << " joint columns");
  VRREG_THROW_UNLESS(point.q_rad.rows() == n_joints && n_joints > 0,
                     "Strategy 2: point " << p << " has " << point.q_rad.rows()
                                          << " joints, point 0 has " << n_joints);
  VRREG_THROW_UNLESS(point.q_rad.allFinite(),
                     "Strategy 2: point " << p << " has non-finite joints");
  const std::set<int> distinct(point.labels.begin(), point.labels.end());
  VRREG_THROW_UNLESS(distinct.size() == point.labels.size(),
                     "Strategy 2: point " << p << " lists a configuration label twice");
}

// Columns of `point` in label order (the order Strategy 1 uses).
std::vector<int> label_order(const PointConfigurations& point) {
  std::vector<int> order(point.labels.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return point.labels[static_cast<std::size_t>(a)] < point.labels[static_cast<std::size_t>(b)];
  });
  return order;
}

}  // namespace

JointNorm parse_joint_norm(std::string_view name) {
  if (name == "l2") return JointNorm::kL2;
  if (name == "linf") return JointNorm::kLinf;
  VRREG_THROW_UNLESS(false,
                     "unknown joint norm '" << std::string(name) << "' (expected l2 or linf)");
}

double PathRelabelling::switched_points_fraction() const {
  return labels.empty()
             ? 0.0
             : static_cast<double>(n_switched_points) / static_cast<double>(labels.size());
}

double PathRelabelling::switched_locations_fraction() const {
  return n_configurations == 0
             ? 0.0
             : static_cast<double>(n_switched) / static_cast<double>(n_configurations);
}

PathRelabelling relabel_along_path(const std::vector<PointConfigurations>& path, JointNorm norm,
                                   const JointKinds& kinds) {
  PathRelabelling out;
  if (path.empty()) return out;
  std::set<int> used;
  for (std::size_t p = 0; p < path.size(); ++p) {
    check_point(path[p], p, path.front().q_rad.rows());
    used.insert(path[p].labels.begin(), path[p].labels.end());
  }
  const std::vector<int> rank_label(used.begin(), used.end());

  Eigen::VectorXd reference;
  for (std::size_t p = 0; p < path.size(); ++p) {
    const PointConfigurations& point = path[p];
    const std::vector<int> listed = label_order(point);
    // Candidates in label order, so that ties resolve to the smaller label.
    Eigen::MatrixXd q(point.q_rad.rows(), point.q_rad.cols());
    for (std::size_t k = 0; k < listed.size(); ++k) {
      q.col(static_cast<Eigen::Index>(k)) = point.q_rad.col(listed[k]);
    }
    const int ref = p == 0 ? 0 : *nearest_configuration(q, reference, norm, kinds);
    reference = q.col(ref);
    std::vector<int> ranked = order_by_distance(q, reference, norm, kinds);
    // The reference is at distance 0 and comes first unless an identical configuration precedes.
    ranked.erase(std::find(ranked.begin(), ranked.end(), ref));
    ranked.insert(ranked.begin(), ref);

    std::vector<int> labels(point.labels.size());
    bool point_switched = false;
    for (std::size_t r = 0; r < ranked.size(); ++r) {
      const auto column = static_cast<std::size_t>(listed[static_cast<std::size_t>(ranked[r])]);
      labels[column] = rank_label[r];
      if (labels[column] != point.labels[column]) {
        ++out.n_switched;
        point_switched = true;
      }
    }
    if (point_switched) ++out.n_switched_points;
    out.n_configurations += static_cast<int>(labels.size());
    out.reference.push_back(listed[static_cast<std::size_t>(ref)]);
    out.labels.push_back(std::move(labels));
  }
  return out;
}

}  // namespace vrreg::kinematics
