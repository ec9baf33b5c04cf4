// SPDX-License-Identifier: Apache-2.0
// The finest lattice with its empty nodes filled (docs/field-models.md): one affine fit per empty
// node from the fiducials of its 3 x 3 x 3 block, then the complete grid's trilinear weights.
#include "vrreg/correction/filled_lattice.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "lattice.hpp"
#include "loo_stencil.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/correction/grid.hpp"
#include "vrreg/correction/rrbc.hpp"

namespace vrreg {
namespace {

constexpr std::int64_t kMaxNodesPerFiducial = 64;  // beyond: a sparse layout, not a lattice

}  // namespace

std::string FilledLattice::describe() const {
  std::ostringstream out;
  out << "lattice " << grid.nodes[0] << " x " << grid.nodes[1] << " x " << grid.nodes[2]
      << " nodes, " << units::m_to_mm(grid.spacing_m.x()) << " x "
      << units::m_to_mm(grid.spacing_m.y()) << " x " << units::m_to_mm(grid.spacing_m.z())
      << " mm: " << n_fiducial_nodes << " fiducials, "
      << n_filled << " empty nodes filled from their neighbours";
  if (n_empty > 0) out << ", " << n_empty << " left empty";
  return out.str();
}

std::optional<FilledLattice> try_fill_lattice(const ConstPoints3Ref& fiducials_robot_m,
                                              const ConstPoints3Ref& corrections_sensor_m,
                                              double tolerance_m, std::string& why) {
  VRREG_THROW_UNLESS(corrections_sensor_m.cols() == fiducials_robot_m.cols(),
                     "got " << corrections_sensor_m.cols() << " corrections for "
                            << fiducials_robot_m.cols() << " fiducials");
  VRREG_THROW_UNLESS(fiducials_robot_m.allFinite() && corrections_sensor_m.allFinite(),
                     "trilinear interpolation needs fiducials with finite positions and "
                     "corrections");
  if (fiducials_robot_m.cols() < 8) {
    why = "trilinear interpolation needs at least 8 fiducials, got " +
          std::to_string(fiducials_robot_m.cols());
    return std::nullopt;
  }
  VRREG_THROW_UNLESS(std::isfinite(tolerance_m) && tolerance_m > 0.0,
                     "the match tolerance must be > 0, got " << tolerance_m << " m");
  std::string reason;
  const auto lattice = detail::fit_lattice(fiducials_robot_m, tolerance_m, reason);
  if (!lattice) {
    why = "trilinear interpolation needs fiducials on a lattice: " + reason;
    return std::nullopt;
  }
  FilledLattice out;
  GridLayout& grid = out.grid;
  std::int64_t total = 1;
  for (std::size_t a = 0; a < 3; ++a) {
    grid.origin_m(static_cast<Eigen::Index>(a)) = lattice->axes[a].origin_m;
    grid.spacing_m(static_cast<Eigen::Index>(a)) = lattice->axes[a].spacing_m;
    grid.nodes[a] = lattice->axes[a].size();
    total *= grid.nodes[a];
  }
  if (grid.nodes[0] < 2 || grid.nodes[1] < 2 || grid.nodes[2] < 2 ||
      total > kMaxNodesPerFiducial * fiducials_robot_m.cols()) {
    std::ostringstream message;
    message << "trilinear interpolation needs a filled lattice: the " << grid.nodes[0] << " x "
            << grid.nodes[1] << " x " << grid.nodes[2] << " lattice has " << total
            << " nodes for " << fiducials_robot_m.cols()
            << " fiducials (use kriging or scattered)";
    why = message.str();
    return std::nullopt;
  }
  grid.n_fiducials = total;
  grid.fiducial.resize(static_cast<std::size_t>(total));
  for (std::int64_t n = 0; n < total; ++n) grid.fiducial[static_cast<std::size_t>(n)] = n;
  out.node_corrections_sensor_m.setConstant(3, total, std::numeric_limits<double>::quiet_NaN());
  for (const auto& [key, column] : lattice->node_fiducial) {
    out.node_corrections_sensor_m.col(key) = corrections_sensor_m.col(column);
  }
  out.n_fiducial_nodes = static_cast<Eigen::Index>(lattice->node_fiducial.size());
  for (int k = 0; k < grid.nodes[2]; ++k) {
    for (int j = 0; j < grid.nodes[1]; ++j) {
      for (int i = 0; i < grid.nodes[0]; ++i) {
        const std::int64_t key = lattice->key(i, j, k);
        if (lattice->node_fiducial.contains(key)) continue;
        std::vector<Eigen::Index> block;
        std::vector<Eigen::Index> faces;  // the 6 nearest nodes
        for (int dk = -1; dk <= 1; ++dk) {
          for (int dj = -1; dj <= 1; ++dj) {
            for (int di = -1; di <= 1; ++di) {
              const int a = i + di;
              const int b = j + dj;
              const int c = k + dk;
              if (a < 0 || b < 0 || c < 0 || a >= grid.nodes[0] || b >= grid.nodes[1] ||
                  c >= grid.nodes[2])
                continue;
              const auto it = lattice->node_fiducial.find(lattice->key(a, b, c));
              if (it == lattice->node_fiducial.end()) continue;
              block.push_back(it->second);
              if (std::abs(di) + std::abs(dj) + std::abs(dk) == 1) faces.push_back(it->second);
            }
          }
        }
        const Eigen::Vector3d node_m =
            grid.origin_m + Eigen::Vector3d(i, j, k).cwiseProduct(grid.spacing_m);
        // The 6 face neighbours when all are there (nearest: least smoothing), else the block.
        detail::LooStencil s = detail::affine_stencil(fiducials_robot_m, node_m, std::move(faces));
        if (!s.ok) s = detail::affine_stencil(fiducials_robot_m, node_m, std::move(block));
        if (!s.ok) {
          ++out.n_empty;
          continue;
        }
        Eigen::Vector3d value = Eigen::Vector3d::Zero();
        for (std::size_t n = 0; n < s.fiducial.size(); ++n)
          value += s.weight[n] * corrections_sensor_m.col(s.fiducial[n]);
        out.node_corrections_sensor_m.col(key) = value;
        ++out.n_filled;
      }
    }
  }
  return out;
}

FilledLattice fill_lattice(const ConstPoints3Ref& fiducials_robot_m,
                           const ConstPoints3Ref& corrections_sensor_m, double tolerance_m) {
  std::string why;
  std::optional<FilledLattice> out =
      try_fill_lattice(fiducials_robot_m, corrections_sensor_m, tolerance_m, why);
  VRREG_THROW_UNLESS(out, why);
  return std::move(*out);
}

std::optional<Eigen::Vector3d> lattice_correction(const FilledLattice& lattice,
                                                  const Eigen::Vector3d& point_robot_m,
                                                  double tolerance_m) {
  const Stencil stencil = grid_stencil(lattice.grid, point_robot_m, tolerance_m);
  if (stencil.status != StencilStatus::kOk) return std::nullopt;
  for (int c = 0; c < stencil.size; ++c) {
    if (std::isnan(lattice.node_corrections_sensor_m(0, stencil.fiducial[static_cast<std::size_t>(c)])))
      return std::nullopt;
  }
  return interpolate_correction(stencil, lattice.node_corrections_sensor_m);
}

}  // namespace vrreg
