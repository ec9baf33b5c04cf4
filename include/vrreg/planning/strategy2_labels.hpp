// SPDX-License-Identifier: Apache-2.0
#pragma once
// Strategy 2 of Procedure 2 (paper section 4.4) on a measurement set: every location (fiducial
// and target) gets the label its configuration earns along the visiting path, so `--config N`
// then selects arms that are alike from point to point.
#include <map>

#include "vrreg/core/measurement.hpp"
#include "vrreg/kinematics/joint_distance.hpp"

namespace vrreg::planning {

/// What the relabelling changed.
struct Strategy2Summary {
  kinematics::JointNorm norm = kinematics::JointNorm::kL2;
  int n_points = 0;           ///< nominal points on the path (distinct point labels)
  int n_locations = 0;        ///< (point, config) locations relabelled
  int n_switched = 0;         ///< locations whose new label differs from the file's
  int n_switched_points = 0;  ///< points with at least one switched location
  std::map<int, int> switched_by_file_label{};  ///< n_switched split by the label in the file
  /// n_switched_points / n_points: the paper's "roughly 14 % of nominal locations were switched"
  /// (section 5.2, all in configurations 1-3). The CLI's `switched_fraction` is this one.
  [[nodiscard]] double switched_points_fraction() const;
  /// n_switched / n_locations: the share of (point, config) locations relabelled.
  [[nodiscard]] double switched_locations_fraction() const;
};

/// The relabelled set and what changed.
struct Strategy2Result {
  MeasurementSet set{};  ///< a copy of the input with Strategy 2 labels in Location::config
  Strategy2Summary summary{};
};

/// Strategy 2 (section 4.4): the visiting path is the order in which the point labels first
/// appear in `set`; each point's locations are its configurations (kinematics::relabel_along_path).
/// Throws InputError (without the file name) when the set has no config column, no joint columns,
/// or a location without a label or joints.
Strategy2Result relabel_strategy2(const MeasurementSet& set,
                                  kinematics::JointNorm norm = kinematics::JointNorm::kL2,
                                  const kinematics::JointKinds& kinds = {});

}  // namespace vrreg::planning
