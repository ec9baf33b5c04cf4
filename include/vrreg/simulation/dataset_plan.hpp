// SPDX-License-Identifier: Apache-2.0
#pragma once
// The paper's datasets as lists of nominal locations in visiting order (sections 4.1, 4.2):
// UR5 A1 / A2 (regular grids, targets at odd grid indices), B (the A1 targets, each with ten
// octuplet cubes of edge 50 -> 5 mm) and the LWR 4+ grid (a serpentine path of unit steps).
#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::simulation {

/// A dataset of the paper, or a user's plan (Procedure 1, measured with simulate_plan).
enum class Dataset { kA1, kA2, kB, kGrid, kPlan };

/// "A1", "A2", "B", "grid" or "plan".
const char* to_string(Dataset dataset);
/// Parses a dataset name of the paper (case-insensitive; not "plan"); throws InputError otherwise.
Dataset parse_dataset(std::string_view name);
/// Throws InputError unless `dataset` belongs to test bed `kind` (UR5: A1, A2, B; LWR: grid;
/// both: plan).
void check_dataset(TestbedKind kind, Dataset dataset);

/// A regular grid of nx x ny x nz nodes with spacing step_m, centred on the work volume.
struct GridSpec {
  int nx = 0;
  int ny = 0;
  int nz = 0;
  double step_m = 0.0;
};

/// The grid of a grid dataset (A1, A2, grid); B uses A1's; throws InputError for a plan.
GridSpec grid_spec(Dataset dataset);

/// Grid nodes (i, j, k) in serpentine order: x fastest, the x direction reversing on every row and
/// the y direction on every layer, so consecutive nodes are always one step apart.
std::vector<Eigen::Vector3i> serpentine_order(int nx, int ny, int nz);

/// One nominal location to visit.
struct PlannedLocation {
  std::string point{};  ///< label, unique per location ("p03_05_02"; B: "p01_01_01_a25_c3")
  Role role = Role::kFiducial;
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();  ///< nominal TCP position, base frame [m]
  int owner = -1;            ///< B: index of the target location this fiducial surrounds
  double cube_edge_m = 0.0;  ///< B: edge of the octuplet cube this fiducial is a corner of
};

/// The nominal locations of `dataset` on test bed `testbed`, in visiting order (not for a plan:
/// InputError).
std::vector<PlannedLocation> plan_dataset(const Testbed& testbed, Dataset dataset);

}  // namespace vrreg::simulation
