#pragma once
// Strategy 2 of Procedure 2 (paper section 4.4): relabel the arm configurations of each nominal
// point along the visiting path so that a label means a similar arm from point to point.
#include <Eigen/Core>
#include <vector>

#include "vrreg/kinematics/joint_distance.hpp"

namespace vrreg::experiments {

/// Strategy 2 order. `configurations[p]` holds the configurations of path point p as columns
/// (joints [rad]) in the Strategy 1 order. Reference = first configuration of the first point;
/// at each next point the configuration nearest the previous reference becomes the reference;
/// the others follow sorted by distance to it. Returns, per point, the Strategy 1 column of each
/// new label: order[p][m] is the column that gets label m + 1.
std::vector<std::vector<int>> strategy2_order(
    const std::vector<Eigen::MatrixXd>& configurations,
    kinematics::JointNorm norm = kinematics::JointNorm::kL2);

/// Fraction of points whose Strategy 2 order differs from the Strategy 1 order (paper: 14 %).
double switched_fraction(const std::vector<std::vector<int>>& order);

}  // namespace vrreg::experiments
