// SPDX-License-Identifier: Apache-2.0
#pragma once
// Cells for judging extrapolation (docs/uncertainty.md): fiducials on a small lattice and
// targets 1, 10 or 100 times the lattice's size beyond it, under physics whose error far away is
// known: a tracker's bounded warp, a tracker's scale error (an error that keeps growing), or a
// test bed's robot (DH errors, transmission ripple, compliance) where the arm reaches.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg::simulation {

/// What makes the error a target far from the fiducials sees.
enum class FarPhysics {
  /// The tracker's distortion: three plane waves of 0.15-0.6 m wavelength, ~0.1 mm each
  /// (bounded: far away it stays the size it has inside).
  kTrackerWarp,
  /// The tracker's distortion along its axes: each robot-frame component a wave of its own
  /// coordinate, 0.1-0.15 mm, 0.25-0.4 m wavelength (bounded, and the registration absorbs no
  /// rotation from it).
  kTrackerAxisWarp,
  /// The tracker's scale error (1e-4..5e-4) and shear about its own origin 2 m away, plus a warp
  /// a fifth of kTrackerWarp's (it grows with the distance without bound).
  kTrackerScale,
  /// kTrackerAxisWarp and kTrackerScale's affine part together.
  kTrackerAxisWarpAndScale,
  /// The UR5 test bed's robot and tracker (DH errors, transmission ripple); targets only where
  /// the arm reaches them.
  kUr5Robot,
  /// The KUKA LWR 4+ test bed's (DH errors, ripple, joint compliance under gravity).
  kLwr4Robot,
};

/// "warp", "scale", "ur5", "lwr4".
const char* to_string(FarPhysics physics);

struct FarFieldCellOptions {
  FarPhysics physics = FarPhysics::kTrackerWarp;
  int nodes = 4;             ///< fiducials per axis of the lattice (>= 2)
  double spacing_m = 0.02;   ///< lattice spacing [m]
  int repeats = 1;           ///< readings per location (averaged)
  /// Noise of one reading per axis [m]; the robot physics keep their test bed's when 0.
  double noise_sd_m = 2e-5;
  /// How far beyond the lattice's box the targets lie, in lattice sizes (its largest extent).
  std::vector<double> distances{1.0, 10.0, 100.0};
  int directions = 8;      ///< targets per distance, in random directions
  std::uint64_t seed = 1;  ///< the field, the tracker's pose, the directions and the noise
  /// Throws InputError on a value out of range.
  void validate() const;
};

/// One far-field cell: fiducials and targets, nominal robot positions and averaged readings.
struct FarFieldCell {
  Points3 fiducials_robot_m{};   ///< nominal (commanded) positions, robot frame [m]
  Points3 fiducials_sensor_m{};  ///< the mean of their readings, sensor frame [m]
  Eigen::MatrixXd fiducials_q_rad{};  ///< commanded joints (robot physics), else 0 x 0
  Points3 targets_robot_m{};
  Points3 targets_sensor_m{};
  Eigen::MatrixXd targets_q_rad{};
  std::vector<double> target_distance{};  ///< each target's distance option (in lattice sizes)
  double noise_sd_m = 0.0;  ///< noise of one averaged reading per axis [m]
  std::string robot{};      ///< the test bed's name for the robot physics, else empty
};

/// Draws the cell of `options` (same options, same cell, bit for bit).
FarFieldCell far_field_cell(const FarFieldCellOptions& options);

}  // namespace vrreg::simulation
