// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/grid.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "grid_stencil.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg {
namespace {

std::string ordinal(int n) {
  if (n % 100 >= 11 && n % 100 <= 13) return std::to_string(n) + "th";
  switch (n % 10) {
    case 1:
      return std::to_string(n) + "st";
    case 2:
      return std::to_string(n) + "nd";
    case 3:
      return std::to_string(n) + "rd";
    default:
      return std::to_string(n) + "th";
  }
}

}  // namespace

std::string GridLayout::describe() const {
  std::ostringstream out;
  out << "grid " << nodes[0] << " x " << nodes[1] << " x " << nodes[2] << " nodes, "
      << units::m_to_mm(spacing_m.x()) << " x " << units::m_to_mm(spacing_m.y()) << " x "
      << units::m_to_mm(spacing_m.z()) << " mm";
  if (stride > 1) {
    out << " (every " << ordinal(stride) << " fiducial; " << fiducial.size() << " of "
        << n_fiducials << " fiducials)";
  }
  return out.str();
}

namespace detail {

std::array<double, 3> grid_slack(const GridLayout& grid, double tolerance_m) {
  return {tolerance_m / grid.spacing_m.x(), tolerance_m / grid.spacing_m.y(),
          tolerance_m / grid.spacing_m.z()};
}

void grid_stencil_into(const GridLayout& grid, const Eigen::Vector3d& point_robot_m,
                       const std::array<double, 3>& slack, Stencil& out) {
  std::array<int, 3> cell{};
  std::array<double, 3> fraction{};
  for (int axis = 0; axis < 3; ++axis) {
    const auto a = static_cast<std::size_t>(axis);
    const double last = grid.nodes[a] - 1;
    const double t = (point_robot_m(axis) - grid.origin_m(axis)) / grid.spacing_m(axis);
    if (!(t >= -slack[a] && t <= last + slack[a])) {  // also catches NaN
      out = Stencil{
          .fiducial = {}, .weight = {}, .size = 0, .status = StencilStatus::kOutsideGrid};
      return;
    }
    const double clamped = std::clamp(t, 0.0, last);
    // clamped >= 0, so truncation is floor (without SSE4.1 std::floor is a library call).
    cell[a] = std::min(static_cast<int>(clamped), grid.nodes[a] - 2);
    fraction[a] = clamped - cell[a];
  }
  out.size = 8;
  out.status = StencilStatus::kOk;
  for (std::size_t corner = 0; corner < 8; ++corner) {
    const int bx = static_cast<int>(corner & 1U);
    const int by = static_cast<int>((corner >> 1U) & 1U);
    const int bz = static_cast<int>((corner >> 2U) & 1U);
    out.fiducial[corner] = grid.node_fiducial(cell[0] + bx, cell[1] + by, cell[2] + bz);
    out.weight[corner] = (bx != 0 ? fraction[0] : 1.0 - fraction[0]) *
                         (by != 0 ? fraction[1] : 1.0 - fraction[1]) *
                         (bz != 0 ? fraction[2] : 1.0 - fraction[2]);
  }
}

}  // namespace detail

Stencil grid_stencil(const GridLayout& grid, const Eigen::Vector3d& point_robot_m,
                     double tolerance_m) {
  Stencil out;
  detail::grid_stencil_into(grid, point_robot_m, detail::grid_slack(grid, tolerance_m), out);
  return out;
}

}  // namespace vrreg
