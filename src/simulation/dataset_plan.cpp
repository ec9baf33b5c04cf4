// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/dataset_plan.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

#include "vrreg/core/check.hpp"

namespace vrreg::simulation {
namespace {

std::string grid_label(const Eigen::Vector3i& node) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "p%02d_%02d_%02d", node.x(), node.y(), node.z());
  return buffer;
}

bool all_odd(const Eigen::Vector3i& node) {
  return node.x() % 2 == 1 && node.y() % 2 == 1 && node.z() % 2 == 1;
}

// Nominal positions are round numbers of millimetres; this picks the double in metres (of the
// two or three nearest mm / 1000) that converts back to exactly that number, so that files show
// "325" and not "325.00000000000006".
double metres_of_mm(double mm) {
  const double m = mm / 1000.0;
  for (double candidate : {m, std::nextafter(m, std::numeric_limits<double>::infinity()),
                           std::nextafter(m, -std::numeric_limits<double>::infinity())}) {
    if (candidate * 1000.0 == mm) return candidate;
  }
  return m;
}

Eigen::Vector3d metres_of_mm(const Eigen::Vector3d& mm) {
  return {metres_of_mm(mm.x()), metres_of_mm(mm.y()), metres_of_mm(mm.z())};
}

// Grid node position in mm, rounded to 1 um (exact for the grids and cubes used here).
Eigen::Vector3d node_position_mm(const Testbed& testbed, const GridSpec& grid,
                                 const Eigen::Vector3i& node) {
  const Eigen::Vector3d centre_index(0.5 * (grid.nx - 1), 0.5 * (grid.ny - 1), 0.5 * (grid.nz - 1));
  const Eigen::Vector3d centre_mm = (testbed.volume_centre_m * 1e6).array().round() / 1e3;
  const double step_mm = std::round(grid.step_m * 1e6) / 1e3;
  return centre_mm + step_mm * (node.cast<double>() - centre_index);
}

std::vector<PlannedLocation> plan_grid(const Testbed& testbed, const GridSpec& grid) {
  std::vector<PlannedLocation> plan;
  for (const Eigen::Vector3i& node : serpentine_order(grid.nx, grid.ny, grid.nz)) {
    plan.push_back({grid_label(node), all_odd(node) ? Role::kTarget : Role::kFiducial,
                    metres_of_mm(node_position_mm(testbed, grid, node)), -1, 0.0});
  }
  return plan;
}

// B: the A1 targets in serpentine order over the target grid; each target, then its ten cubes
// from 50 to 5 mm, corners with x fastest (corner bits: 1 = +x, 2 = +y, 4 = +z).
std::vector<PlannedLocation> plan_b(const Testbed& testbed) {
  const GridSpec grid = grid_spec(Dataset::kA1);
  std::vector<PlannedLocation> plan;
  for (const Eigen::Vector3i& t : serpentine_order(grid.nx / 2, grid.ny / 2, grid.nz / 2)) {
    const Eigen::Vector3i node = 2 * t + Eigen::Vector3i::Ones();
    const std::string label = grid_label(node);
    const Eigen::Vector3d centre_mm = node_position_mm(testbed, grid, node);
    const int owner = static_cast<int>(plan.size());
    plan.push_back({label, Role::kTarget, metres_of_mm(centre_mm), -1, 0.0});
    for (int edge_mm = 50; edge_mm >= 5; edge_mm -= 5) {
      const double edge_m = 1e-3 * edge_mm;
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d sign((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0,
                                   (corner & 4) ? 1.0 : -1.0);
        char suffix[48];
        std::snprintf(suffix, sizeof suffix, "_a%02d_c%d", edge_mm, corner);
        plan.push_back({label + suffix, Role::kFiducial,
                        metres_of_mm(centre_mm + 0.5 * edge_mm * sign), owner, edge_m});
      }
    }
  }
  return plan;
}

}  // namespace

const char* to_string(Dataset dataset) {
  switch (dataset) {
    case Dataset::kA1:
      return "A1";
    case Dataset::kA2:
      return "A2";
    case Dataset::kB:
      return "B";
    case Dataset::kPlan:
      return "plan";
    case Dataset::kGrid:
      break;
  }
  return "grid";
}

Dataset parse_dataset(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "a1") return Dataset::kA1;
  if (lower == "a2") return Dataset::kA2;
  if (lower == "b") return Dataset::kB;
  if (lower == "grid") return Dataset::kGrid;
  VRREG_THROW_UNLESS(false, "unknown dataset '" << std::string(name)
                                                << "' (use A1, A2 or B for ur5, grid for lwr4)");
  return Dataset::kA1;  // not reached
}

void check_dataset(TestbedKind kind, Dataset dataset) {
  if (dataset == Dataset::kPlan) return;
  const bool ur = kind == TestbedKind::kUr5;
  VRREG_THROW_UNLESS(ur == (dataset != Dataset::kGrid),
                     "dataset " << to_string(dataset) << " does not belong to test bed "
                                << (ur ? "ur5 (use A1, A2 or B)" : "lwr4 (use grid)"));
}

GridSpec grid_spec(Dataset dataset) {
  switch (dataset) {
    case Dataset::kA1:
    case Dataset::kB:
      return {11, 13, 9, 25e-3};
    case Dataset::kA2:
      return {21, 25, 17, 12.5e-3};
    case Dataset::kPlan:
      VRREG_THROW_UNLESS(false, "a plan has no grid of the paper's");
      break;
    case Dataset::kGrid:
      break;
  }
  return {13, 11, 11, 20e-3};
}

std::vector<Eigen::Vector3i> serpentine_order(int nx, int ny, int nz) {
  VRREG_THROW_UNLESS(nx > 0 && ny > 0 && nz > 0,
                     "serpentine order: grid " << nx << " x " << ny << " x " << nz << " is empty");
  std::vector<Eigen::Vector3i> order;
  order.reserve(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) *
                static_cast<std::size_t>(nz));
  int row = 0;  // rows visited so far: the x direction alternates with it
  for (int k = 0; k < nz; ++k) {
    for (int jj = 0; jj < ny; ++jj, ++row) {
      const int j = k % 2 == 0 ? jj : ny - 1 - jj;
      for (int ii = 0; ii < nx; ++ii) {
        const int i = row % 2 == 0 ? ii : nx - 1 - ii;
        order.emplace_back(i, j, k);
      }
    }
  }
  return order;
}

std::vector<PlannedLocation> plan_dataset(const Testbed& testbed, Dataset dataset) {
  VRREG_THROW_UNLESS(dataset != Dataset::kPlan,
                     "a plan's locations come from its file (simulate_plan), not the paper's");
  check_dataset(testbed.kind, dataset);
  if (dataset == Dataset::kB) return plan_b(testbed);
  return plan_grid(testbed, grid_spec(dataset));
}

}  // namespace vrreg::simulation
