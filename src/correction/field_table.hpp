// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to correction: a fitted correction field sampled on a regular lattice over its
// support box and read back by tricubic (Catmull-Rom) interpolation of the correction and
// trilinear interpolation of the predicted sd (with the table's own RMS deviation in
// quadrature): microseconds per point where the exact model
// (kriging's posterior sd: O(J^2) per point) takes milliseconds. Catmull-Rom reproduces
// quadratic fields exactly; the deviation from the exact model is measured when the table is
// built and stated with it.
#include <Eigen/Core>
#include <array>
#include <optional>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/method_state.hpp"

namespace vrreg::detail {

struct FieldTable {
  Eigen::Vector3d support_lo_m = Eigen::Vector3d::Zero();  ///< the box the table answers in [m]
  Eigen::Vector3d support_hi_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();  ///< node (0, 0, 0) [m]
  double spacing_m = 0.0;                              ///< node spacing, every axis [m]
  std::array<Eigen::Index, 3> nodes{};                 ///< per axis, x fastest
  /// Per node: correction x, y, z (sensor frame) and sd [m]; 4 x nodes.
  Eigen::MatrixXd values;
  bool has_sd = false;
  /// Measured against the exact model at check points inside the support box [m, relative].
  double max_correction_deviation_m = 0.0;
  double max_sd_relative_deviation = 0.0;
  /// RMS over the check points of the 3D correction deviation [m]: added in quadrature to every
  /// sd the table answers, since a target meets the table's deviation as one more error source.
  double rms_correction_deviation_m = 0.0;
  /// The smallest sd of the exact model at the check points [m] (0 without an sd).
  double min_model_sd_m = 0.0;
  Eigen::Index n_checked = 0;

  /// The lattice of spacing `spacing_m` whose Catmull-Rom stencils cover [lo, hi] (one node
  /// beyond the box before it, two after); values still to be filled.
  static FieldTable over(const Eigen::Vector3d& lo_m, const Eigen::Vector3d& hi_m,
                         double spacing_m);
  [[nodiscard]] Eigen::Index size() const { return nodes[0] * nodes[1] * nodes[2]; }
  /// The position of node n [m].
  [[nodiscard]] Eigen::Vector3d node_m(Eigen::Index n) const;
  /// Correction and sd at `point_m`, or nullopt outside the support box (by more than
  /// `tolerance_m`).
  [[nodiscard]] bool lookup(const Eigen::Vector3d& point_m, double tolerance_m,
                            Eigen::Vector3d& correction_m, double& sd_m) const;

  void save(MethodState& state) const;
  static FieldTable restore(const MethodState& state);
};

}  // namespace vrreg::detail
