// SPDX-License-Identifier: Apache-2.0
#pragma once
// Trilinear interpolation on the finest lattice of a fiducial layout even when nodes hold no
// fiducial (beyond the paper: A1's 25 mm grid has a hole at every target): each empty node is
// filled with the affine least-squares prediction from the fiducials around it, then Eq. 7's
// trilinear weights apply as on a complete grid.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/grid.hpp"

namespace vrreg {

/// The base lattice of a layout with a correction at every node it could give one.
struct FilledLattice {
  /// The lattice as a complete grid whose "fiducial" at node n is column n of the corrections.
  GridLayout grid{};
  /// Correction per node (x fastest), sensor frame [m]; NaN where the node stayed empty.
  Points3 node_corrections_sensor_m{};
  Eigen::Index n_fiducial_nodes = 0;  ///< nodes holding a fiducial
  Eigen::Index n_filled = 0;          ///< empty nodes filled from their neighbours
  Eigen::Index n_empty = 0;           ///< nodes left without a correction (too few neighbours)
  /// E.g. "lattice 13 x 13 x 9 nodes, 25 x 25 x 25 mm: 1167 fiducials, 120 nodes filled".
  [[nodiscard]] std::string describe() const;
};

/// Fits the lattice of fiducials_robot_m [m] (levels within tolerance_m) and fills each empty
/// node from the fiducials of its 3 x 3 x 3 block (an affine fit, >= 6 of them, not all in a
/// plane). Throws InputError when the fiducials are not on an evenly spaced lattice, or the
/// lattice would have more than 64 nodes per fiducial (a sparse layout: use kriging instead).
[[nodiscard]] FilledLattice fill_lattice(const ConstPoints3Ref& fiducials_robot_m,
                                         const ConstPoints3Ref& corrections_sensor_m,
                                         double tolerance_m);

/// fill_lattice, with the reason in `why` and nullopt instead of an exception when the fiducials
/// hold no usable lattice (fewer than 8, not evenly spaced, too sparse); still throws on
/// non-finite input or a bad tolerance.
[[nodiscard]] std::optional<FilledLattice> try_fill_lattice(
    const ConstPoints3Ref& fiducials_robot_m, const ConstPoints3Ref& corrections_sensor_m,
    double tolerance_m, std::string& why);

/// Trilinear interpolation (Eq. 7) of the node corrections in the cell holding point_robot_m
/// [m]; nullopt beyond tolerance_m outside the lattice or when a corner of the cell is empty.
[[nodiscard]] std::optional<Eigen::Vector3d> lattice_correction(
    const FilledLattice& lattice, const Eigen::Vector3d& point_robot_m, double tolerance_m);

}  // namespace vrreg
