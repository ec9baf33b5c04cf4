// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fiducials found by nominal robot position when one position holds several arm configurations
// (Procedure 2, Strategy 3, paper section 4.4): every fiducial at a cube corner around a target
// (Eq. 7) or at a corner of the whole work volume. Which configuration to use is the caller's.
#include <array>
#include <memory>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// The fiducials at each of 8 corners, x fastest (corner bits: 1 = +x, 2 = +y, 4 = +z).
using CornerFiducials = std::array<std::vector<Eigen::Index>, 8>;

/// Looks up fiducials by nominal robot position; positions may repeat (one per configuration).
class CornerCandidates {
 public:
  /// fiducials_robot_m: nominal robot positions [m], at least one; tolerance_m > 0: how far a
  /// fiducial may be from a queried position [m]. Throws InputError on bad input.
  CornerCandidates(const ConstPoints3Ref& fiducials_robot_m, double tolerance_m);
  ~CornerCandidates();
  CornerCandidates(CornerCandidates&&) noexcept;
  CornerCandidates& operator=(CornerCandidates&&) noexcept;

  /// Columns of every fiducial within the tolerance of `position_m` [m], ascending.
  [[nodiscard]] std::vector<Eigen::Index> at(const Eigen::Vector3d& position_m) const;
  /// Fiducials at the corners p + (±a/2, ±a/2, ±a/2) of a cube of edge a = cube_edge_m around the
  /// target's nominal position p [m] (Eq. 7); a corner without fiducials is empty. Throws
  /// InputError unless a > 4 * tolerance.
  [[nodiscard]] CornerFiducials octuplet(const Eigen::Vector3d& target_robot_nominal_m,
                                         double cube_edge_m) const;
  /// Fiducials at the nominal position nearest each corner of the bounding box of all fiducials
  /// (the corners themselves on a full grid) [m]. Throws InputError when two corners would share
  /// a position (a flat or single-point volume).
  [[nodiscard]] CornerFiducials volume_corners() const;
  [[nodiscard]] const Points3& positions_m() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_{};
  double tolerance_m_ = 0.0;
};

}  // namespace vrreg
