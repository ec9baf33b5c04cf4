// SPDX-License-Identifier: Apache-2.0
#pragma once
// Strategy 2 of Procedure 2 (paper section 4.4): relabel the arm configurations of the nominal
// points along the visiting path, so that one label means a similar arm from point to point.
// Plain joint matrices and integer labels; MeasurementSet-level use is in
// planning/strategy2_labels.
#include <Eigen/Core>
#include <string_view>
#include <vector>

#include "vrreg/kinematics/joint_distance.hpp"

namespace vrreg::kinematics {

/// Parses "l2" or "linf" (what to_string(JointNorm) prints); throws InputError otherwise.
JointNorm parse_joint_norm(std::string_view name);

/// The arm configurations measured at one nominal point, as listed (Strategy 1).
struct PointConfigurations {
  std::vector<int> labels{};  ///< label of each configuration (distinct within the point)
  Eigen::MatrixXd q_rad{};  ///< joints, one column per configuration, same order as `labels` [rad]
};

/// New labels along a path: the same shape as the input.
struct PathRelabelling {
  std::vector<std::vector<int>>
      labels{};                          ///< labels[p][k]: new label of configuration k of point p
  std::vector<int> reference{};          ///< per point, the column k of its reference configuration
  int n_configurations = 0;              ///< configurations (locations) on the path
  int n_switched = 0;                    ///< configurations whose new label differs from the old
  int n_switched_points = 0;             ///< points with at least one switched configuration
  /// n_switched_points / points on the path (0 for an empty path): the paper's "14 % of nominal
  /// locations were switched" (section 5.2).
  [[nodiscard]] double switched_points_fraction() const;
  /// n_switched / n_configurations (0 for an empty path): (point, config) locations relabelled.
  [[nodiscard]] double switched_locations_fraction() const;
};

/// Strategy 2 (section 4.4). `path`: the nominal points in visiting order. Point 0's reference is
/// its configuration with the smallest label; at each next point the reference is the
/// configuration nearest (in `norm`, angles wrapped, slides per `kinds`) the previous point's
/// reference. Each point's
/// reference gets rank 1 and the others ranks 2..m by ascending distance to it (ties keep label
/// order). Rank r becomes the r-th smallest label used on the path (1..m for files labelled 1..m).
/// Throws InputError on a point without configurations, repeated labels within a point, joint
/// counts that differ, or non-finite joints.
PathRelabelling relabel_along_path(const std::vector<PointConfigurations>& path,
                                   JointNorm norm = JointNorm::kL2, const JointKinds& kinds = {});

}  // namespace vrreg::kinematics
