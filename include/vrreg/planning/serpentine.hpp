// SPDX-License-Identifier: Apache-2.0
#pragma once
// Visiting order inside one fiducial cube (paper section 4.2, Fig. 2): a 3D serpentine
// (boustrophedon) whose consecutive nodes are always one grid step apart.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

namespace vrreg::planning {

/// One of the 48 serpentines through an n x n x n grid: which corner it starts from and which
/// axis is walked fastest, next and slowest.
struct SerpentineVariant {
  int start_corner = 0;              ///< bit a set: axis a starts at index n - 1 (else 0)
  std::array<int, 3> axes{0, 1, 2};  ///< fast, middle, slow axis (a permutation of 0, 1, 2)
};

/// Number of serpentine variants: 8 start corners x 6 axis orders.
inline constexpr int kSerpentineVariants = 48;

/// Variant `k` in 0..47: start corner k % 8, axis order k / 8 (throws InputError otherwise).
SerpentineVariant serpentine_variant(int k);

/// Grid indices in visiting order: rows along the fast axis, alternating direction, snaking over
/// the middle axis, layers along the slow axis; every consecutive pair differs by exactly 1 in
/// exactly one index (paper Fig. 2). All n^3 nodes once. Throws InputError unless 1 <= n <= 1000.
std::vector<Eigen::Vector3i> serpentine(int nodes_per_axis, const SerpentineVariant& variant);

/// First and last node of serpentine(n, variant), without building it.
std::array<Eigen::Vector3i, 2> serpentine_ends(int nodes_per_axis,
                                               const SerpentineVariant& variant);

/// Grid index that stands for the cube's centre (the target) in a visiting sequence.
inline const Eigen::Vector3i kCentreIndex(-1, -1, -1);

/// Inserts kCentreIndex into `path` (a serpentine of an n x n x n grid, n >= 2) between the
/// consecutive pair of nodes where the detour through the grid's centre is least: for even n two
/// adjacent corners of the centre cell (steps of sqrt(3)/2 grid steps). Returns its position.
std::size_t insert_centre(std::vector<Eigen::Vector3i>& path, int nodes_per_axis);

}  // namespace vrreg::planning
