// SPDX-License-Identifier: Apache-2.0
#pragma once
// Layouts for the correction tests: regular grids, the paper's A1 pattern, affine fields.
#include <Eigen/Core>
#include <algorithm>
#include <numeric>
#include <vector>

#include "vrreg/core/random.hpp"
#include "vrreg/core/types.hpp"

namespace vrreg::testing {

/// Interpolation tests compare to closed forms; 1e-6 m leaves room for round-off only.
inline constexpr double kTolerance = 1e-6;

/// Nodes of an nx x ny x nz grid, x fastest, node (0,0,0) at origin_m [m].
inline Points3 grid_points(int nx, int ny, int nz, const Eigen::Vector3d& spacing_m,
                           const Eigen::Vector3d& origin_m = Eigen::Vector3d::Zero()) {
  Points3 p(3, nx * ny * nz);
  Eigen::Index c = 0;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        p.col(c++) = origin_m + Eigen::Vector3d(i, j, k).cwiseProduct(spacing_m);
      }
    }
  }
  return p;
}

/// The paper's dataset A1 in the robot frame: an 11 x 13 x 9 grid at 25 mm; the nodes with all
/// indices odd (5 x 6 x 4 = 120) are targets, the other 1167 are fiducials.
struct A1Layout {
  Points3 fiducials_robot_m;
  Points3 targets_robot_m;
};
inline A1Layout a1_layout(const Eigen::Vector3d& origin_m = Eigen::Vector3d(0.3, -0.1, 0.05)) {
  std::vector<Eigen::Vector3d> fiducials;
  std::vector<Eigen::Vector3d> targets;
  for (int k = 0; k < 9; ++k) {
    for (int j = 0; j < 13; ++j) {
      for (int i = 0; i < 11; ++i) {
        const Eigen::Vector3d p = origin_m + 0.025 * Eigen::Vector3d(i, j, k);
        ((i % 2 == 1 && j % 2 == 1 && k % 2 == 1) ? targets : fiducials).push_back(p);
      }
    }
  }
  A1Layout out{Points3(3, static_cast<Eigen::Index>(fiducials.size())),
               Points3(3, static_cast<Eigen::Index>(targets.size()))};
  for (std::size_t j = 0; j < fiducials.size(); ++j)
    out.fiducials_robot_m.col(static_cast<Eigen::Index>(j)) = fiducials[j];
  for (std::size_t j = 0; j < targets.size(); ++j)
    out.targets_robot_m.col(static_cast<Eigen::Index>(j)) = targets[j];
  return out;
}

/// A random permutation of 0..n-1.
inline std::vector<Eigen::Index> random_permutation(Random& rng, Eigen::Index n) {
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  for (std::size_t i = order.size(); i > 1; --i) {
    std::swap(order[i - 1], order[static_cast<std::size_t>(rng.below(i))]);
  }
  return order;
}

/// Columns of `points` in the given order.
inline Points3 permuted(const Points3& points, const std::vector<Eigen::Index>& order) {
  Points3 out(3, points.cols());
  for (Eigen::Index j = 0; j < points.cols(); ++j)
    out.col(j) = points.col(order[static_cast<std::size_t>(j)]);
  return out;
}

/// A random affine field f(p) = A p + b with corrections of about a millimetre.
struct AffineField {
  Eigen::Matrix3d a;
  Eigen::Vector3d b;
  [[nodiscard]] Eigen::Vector3d operator()(const Eigen::Vector3d& p) const { return a * p + b; }
  [[nodiscard]] Points3 at(const Points3& points) const {
    Points3 out = a * points;
    out.colwise() += b;
    return out;
  }
};
inline AffineField random_affine_field(Random& rng) {
  AffineField f;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) f.a(r, c) = rng.uniform(-5e-3, 5e-3);
    f.b(r) = rng.uniform(-1e-3, 1e-3);
  }
  return f;
}

}  // namespace vrreg::testing
