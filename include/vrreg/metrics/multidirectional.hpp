// SPDX-License-Identifier: Apache-2.0
#pragma once
// Multi-directional position accuracy (after ISO 9283's multi-directional accuracy variation):
// targets visited from more than one approach direction; per direction the RMS_T, and per target
// point the largest distance between the mean positions reached from its different directions.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// The figures of one approach direction over the targets visited from it.
struct DirectionAccuracy {
  std::vector<double> approach_sign{};  ///< per joint -1, 0, +1 (the direction's key)
  int n_targets = 0;                    ///< target locations visited from this direction
  double unc_rms_t_m = 0.0;             ///< RMS_T of their uncorrected errors (Eq. 4) [m]
  double cor_rms_t_m = 0.0;             ///< and of their corrected errors [m]
};

/// Multi-directional accuracy of the target points visited from two directions or more.
struct MultidirectionalAccuracy {
  int n_points = 0;  ///< target points visited from >= 2 directions (0: nothing to report)
  /// Every direction these points were visited from, in order of first appearance.
  std::vector<DirectionAccuracy> directions{};
  /// Per such point, the largest distance between the mean errors (equivalently the mean reached
  /// positions: one nominal position) of its directions, uncorrected and corrected [m].
  Eigen::VectorXd unc_spread_m{};
  Eigen::VectorXd cor_spread_m{};
  std::vector<std::string> point_names{};  ///< a label per such point (its first target's name)
  double unc_max_spread_m = 0.0;           ///< largest unc_spread_m [m]
  double unc_mean_spread_m = 0.0;          ///< mean of unc_spread_m [m]
  double cor_max_spread_m = 0.0;
  double cor_mean_spread_m = 0.0;
};

/// Groups the targets into points (the same arm configuration and the same non-empty name, or
/// nominal positions within `same_point_m` of each other) and, for the points visited from more
/// than one approach direction (distinct sign vectors), computes the per-direction RMS_T and the
/// spread between the directions' mean positions (ISO 9283's multi-directional position accuracy
/// variation, vAP, with the mean reached positions per direction as its barycentres), uncorrected
/// and corrected. nominal_robot_m, unc_robot_m, cor_robot_m: nominal, uncorrected and corrected
/// positions, robot frame [m], one column per target; approach_sign: per target its n_joints
/// signs, or empty when unknown (left out); names, configs: one per target or empty (a point in
/// two configurations is two points: other joints, not other directions); included: the targets
/// to count (e.g. those corrected), empty = all. Throws InputError on mismatched sizes.
MultidirectionalAccuracy multidirectional_accuracy(
    const ConstPoints3Ref& nominal_robot_m, const ConstPoints3Ref& unc_robot_m,
    const ConstPoints3Ref& cor_robot_m, const std::vector<std::vector<double>>& approach_sign,
    const std::vector<std::string>& names, const std::vector<std::optional<int>>& configs = {},
    const std::vector<bool>& included = {}, double same_point_m = 1e-6);

/// The sign vector as text, one character per joint: '+', '-' or '0'.
std::string approach_text(const std::vector<double>& approach_sign);

}  // namespace vrreg
