// SPDX-License-Identifier: Apache-2.0
#pragma once
// A few points spread over a set (monitor points, fiducials to read again): farthest-point
// sampling, which puts them on the set's extremes first and then fills its middle.
#include <cstddef>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg::planning {

/// Indices of `count` columns of `points_m` [m] (all of them when there are fewer), each the one
/// farthest from those already chosen; the first is the one farthest from the centroid. Ties go
/// to the lower index, so the choice is deterministic. Throws InputError on non-finite points.
std::vector<std::size_t> spread_points(const ConstPoints3Ref& points_m, std::size_t count);

}  // namespace vrreg::planning
