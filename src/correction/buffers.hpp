// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to correction: result buffers of many points (10^6 targets are ~230 MB of results).
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/rrbc.hpp"

namespace vrreg::detail {

/// Sizes a 3 x n result without touching it (the caller writes every entry), on transparent huge
/// pages where Linux offers them: with 4 KiB pages, faulting 10^6 targets' results in cost more
/// than interpolating them.
void allocate_points(Points3& points, Eigen::Index n);

/// Sizes n stencils, their pages faulted in from all threads first (the kernel zeroes each page
/// on its first touch), so that the value-initialisation only writes memory.
void allocate_stencils(std::vector<Stencil>& stencils, Eigen::Index n);

}  // namespace vrreg::detail
