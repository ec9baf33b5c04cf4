// SPDX-License-Identifier: Apache-2.0
#pragma once
// Octuplet stencils (paper section 3.2, dataset B): the 8 fiducials at the corners of a cube of
// edge a centred at a target's nominal robot-frame position, equal weights 1/8 (Eq. 7).
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/rrbc.hpp"

namespace vrreg {

/// Finds cube-corner fiducials by their nominal robot positions (kd-tree), for Eq. 7.
class OctupletStencils {
 public:
  /// fiducials_robot_m: nominal robot positions [m]; cube_edge_m: edge a > 0 [m];
  /// tolerance_m: how far a fiducial may be from a corner [m]. fiducial_sequence: where each
  /// fiducial was read (e.g. its file line), or empty. Without a sequence two fiducials sharing a
  /// nominal position are an InputError; with one, a corner measured more than once (dataset B:
  /// neighbouring targets' cubes share corners) takes the reading nearest the target's in sequence.
  OctupletStencils(const ConstPoints3Ref& fiducials_robot_m, double cube_edge_m,
                   double tolerance_m, std::vector<std::size_t> fiducial_sequence = {});
  ~OctupletStencils();
  OctupletStencils(OctupletStencils&&) noexcept;
  OctupletStencils& operator=(OctupletStencils&&) noexcept;

  /// Corners p + (±a/2, ±a/2, ±a/2) of target_robot_nominal_m [m], x fastest, weights 1/8
  /// (Eq. 7); status kMissingCorner when a corner has no fiducial.
  [[nodiscard]] Stencil stencil(const Eigen::Vector3d& target_robot_nominal_m,
                                std::size_t target_sequence = 0) const;
  /// E.g. "octuplet, cube edge 50 mm".
  [[nodiscard]] std::string describe() const;
  [[nodiscard]] double cube_edge_m() const { return cube_edge_m_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_{};
  double cube_edge_m_ = 0.0;
  double tolerance_m_ = 0.0;
  std::vector<std::size_t> sequence_{};
};

}  // namespace vrreg
