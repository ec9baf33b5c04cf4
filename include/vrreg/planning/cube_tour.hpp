// SPDX-License-Identifier: Apache-2.0
#pragma once
// Order of the M fiducial cubes (paper section 6): the cube sequence and each cube's serpentine
// variant chosen to keep the travel between cubes (last node of one cube to the first of the
// next) short. Open path, free start.
//
// Method: candidate cube sequences are the input order and, from every cube as start (from the
// first 64 when M > 64), a nearest-neighbour tour over the cube centres improved by 2-opt; for
// each candidate an exact dynamic programme over the serpentine variants of every cube picks the
// entry and exit corners; the candidate with the least travel wins. Because the input order is a
// candidate, the result is never worse than the input order with any fixed variants.
#include <Eigen/Core>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg::planning {

/// The cubes' visiting sequence and serpentine variants.
struct CubeTour {
  std::vector<int> order{};      ///< cube indices in visiting order (a permutation of 0..M-1)
  std::vector<int> variant{};    ///< serpentine variant (0..47) of cube order[k], per k
  double between_cubes_m = 0.0;  ///< sum of the exit-to-entry distances between cubes [m]
};

/// Tour over cubes with centres `centres_m` (3 x M); `entry_offsets_m` and `exit_offsets_m`
/// (3 x V) give the first and last node of each of the V variants relative to a cube's centre.
/// Throws InputError when M = 0, V = 0 or the offsets differ in size.
CubeTour plan_cube_tour(const ConstPoints3Ref& centres_m, const ConstPoints3Ref& entry_offsets_m,
                        const ConstPoints3Ref& exit_offsets_m);

/// Travel between cubes [m] for a given order and variants (same arguments as plan_cube_tour).
double between_cube_travel_m(const ConstPoints3Ref& centres_m,
                             const ConstPoints3Ref& entry_offsets_m,
                             const ConstPoints3Ref& exit_offsets_m, const std::vector<int>& order,
                             const std::vector<int>& variant);

}  // namespace vrreg::planning
