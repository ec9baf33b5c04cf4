// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/strategy2_labels.hpp"

#include <string>
#include <unordered_map>
#include <vector>

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/configuration_order.hpp"

namespace vrreg::planning {

double Strategy2Summary::switched_points_fraction() const {
  return n_points == 0 ? 0.0
                       : static_cast<double>(n_switched_points) / static_cast<double>(n_points);
}

double Strategy2Summary::switched_locations_fraction() const {
  return n_locations == 0 ? 0.0
                          : static_cast<double>(n_switched) / static_cast<double>(n_locations);
}

Strategy2Result relabel_strategy2(const MeasurementSet& set, kinematics::JointNorm norm,
                                  const kinematics::JointKinds& kinds) {
  VRREG_THROW_UNLESS(set.has_config,
                     "Strategy 2 needs a config column (the arm configuration of each row)");
  VRREG_THROW_UNLESS(set.n_joints > 0,
                     "Strategy 2 needs joint columns (q1_rad..qN_rad or q1_deg..qN_deg)");
  // Group the locations by point, in the order the points are first visited.
  std::unordered_map<std::string, std::size_t> point_index;
  std::vector<std::vector<std::size_t>> members;
  for (std::size_t i = 0; i < set.locations.size(); ++i) {
    const Location& loc = set.locations[i];
    VRREG_THROW_UNLESS(loc.config.has_value(),
                       "Strategy 2: point '" << loc.point << "' has a row without config");
    VRREG_THROW_UNLESS(loc.q_rad.size() == static_cast<std::size_t>(set.n_joints),
                       "Strategy 2: point '" << loc.point << "' config " << *loc.config << " has "
                                             << loc.q_rad.size() << " joints, expected "
                                             << set.n_joints);
    const auto [it, inserted] = point_index.try_emplace(loc.point, members.size());
    if (inserted) members.emplace_back();
    members[it->second].push_back(i);
  }
  std::vector<kinematics::PointConfigurations> path(members.size());
  for (std::size_t p = 0; p < members.size(); ++p) {
    path[p].q_rad.resize(set.n_joints, static_cast<Eigen::Index>(members[p].size()));
    for (std::size_t k = 0; k < members[p].size(); ++k) {
      const Location& loc = set.locations[members[p][k]];
      path[p].labels.push_back(*loc.config);
      path[p].q_rad.col(static_cast<Eigen::Index>(k)) =
          Eigen::Map<const Eigen::VectorXd>(loc.q_rad.data(), set.n_joints);
    }
  }
  const kinematics::PathRelabelling relabelled = kinematics::relabel_along_path(path, norm, kinds);

  Strategy2Result out{set, {}};
  out.summary.norm = norm;
  out.summary.n_points = static_cast<int>(members.size());
  out.summary.n_locations = relabelled.n_configurations;
  out.summary.n_switched = relabelled.n_switched;
  out.summary.n_switched_points = relabelled.n_switched_points;
  for (std::size_t p = 0; p < members.size(); ++p) {
    for (std::size_t k = 0; k < members[p].size(); ++k) {
      Location& loc = out.set.locations[members[p][k]];
      const int label = relabelled.labels[p][k];
      if (label != *loc.config) ++out.summary.switched_by_file_label[*loc.config];
      loc.config = label;
    }
  }
  return out;
}

}  // namespace vrreg::planning
