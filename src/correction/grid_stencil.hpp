// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal: grid_stencil for many points (correct_targets): the per-axis slack computed once and
// the stencil written in place. Same operations as grid_stencil, so the same bits.
#include <array>

#include "vrreg/correction/grid.hpp"

namespace vrreg::detail {

/// tolerance_m / spacing per axis: how far outside the grid, in cells, a point still counts.
[[nodiscard]] std::array<double, 3> grid_slack(const GridLayout& grid, double tolerance_m);

/// grid_stencil(grid, point_robot_m, tolerance_m) into out, with slack = grid_slack(grid, tol).
void grid_stencil_into(const GridLayout& grid, const Eigen::Vector3d& point_robot_m,
                       const std::array<double, 3>& slack, Stencil& out);

}  // namespace vrreg::detail
