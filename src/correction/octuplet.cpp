// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/octuplet.hpp"

#include <cmath>
#include <sstream>

#include "point_index.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg {

struct OctupletStencils::Impl {
  explicit Impl(const ConstPoints3Ref& points_m) : index(points_m) {}
  detail::PointIndex index;
};

OctupletStencils::OctupletStencils(const ConstPoints3Ref& fiducials_robot_m, double cube_edge_m,
                                   double tolerance_m, std::vector<std::size_t> fiducial_sequence)
    : cube_edge_m_(cube_edge_m), tolerance_m_(tolerance_m), sequence_(std::move(fiducial_sequence)) {
  VRREG_THROW_UNLESS(sequence_.empty() || sequence_.size() == static_cast<std::size_t>(
                                                                   fiducials_robot_m.cols()),
                     "octuplet: " << sequence_.size() << " sequence numbers for "
                                  << fiducials_robot_m.cols() << " fiducials");
  VRREG_THROW_UNLESS(std::isfinite(cube_edge_m) && cube_edge_m > 0.0,
                     "octuplet interpolation needs a cube edge > 0 (got "
                         << units::m_to_mm(cube_edge_m) << " mm): set `cube_edge`");
  VRREG_THROW_UNLESS(
      std::isfinite(tolerance_m) && tolerance_m > 0.0 && tolerance_m < 0.25 * cube_edge_m,
      "octuplet match tolerance must be > 0 and < a/4 (got "
          << units::m_to_mm(tolerance_m) << " mm for a = " << units::m_to_mm(cube_edge_m)
          << " mm)");
  VRREG_THROW_UNLESS(
      fiducials_robot_m.cols() >= 8,
      "octuplet interpolation needs at least 8 fiducials, got " << fiducials_robot_m.cols());
  VRREG_THROW_UNLESS(fiducials_robot_m.allFinite(),
                     "octuplet interpolation: non-finite fiducial coordinates");
  impl_ = std::make_unique<Impl>(fiducials_robot_m);
  if (!sequence_.empty()) return;  // duplicates are resolved per target by sequence
  const auto pair = impl_->index.duplicate(tolerance_m);
  VRREG_THROW_UNLESS(!pair, "fiducials " << (pair ? pair->first : 0) << " and "
                                         << (pair ? pair->second : 0)
                                         << " share a nominal robot position (within "
                                         << units::m_to_mm(tolerance_m)
                                         << " mm): use one arm configuration per model");
}

OctupletStencils::~OctupletStencils() = default;
OctupletStencils::OctupletStencils(OctupletStencils&&) noexcept = default;
OctupletStencils& OctupletStencils::operator=(OctupletStencils&&) noexcept = default;

Stencil OctupletStencils::stencil(const Eigen::Vector3d& target_robot_nominal_m,
                                  std::size_t target_sequence) const {
  Stencil out;
  const double half_m = 0.5 * cube_edge_m_;
  for (std::size_t corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d offset((corner & 1U) != 0 ? half_m : -half_m,
                                 (corner & 2U) != 0 ? half_m : -half_m,
                                 (corner & 4U) != 0 ? half_m : -half_m);
    const Eigen::Vector3d corner_m = target_robot_nominal_m + offset;
    Eigen::Index chosen = impl_->index.nearest(corner_m);
    if ((impl_->index.points().col(chosen) - corner_m).norm() > tolerance_m_) {
      return Stencil{
          .fiducial = {}, .weight = {}, .size = 0, .status = StencilStatus::kMissingCorner};
    }
    if (!sequence_.empty()) {
      // The reading taken closest in time to the target's (its own cube's, in dataset B).
      const auto gap = [&](Eigen::Index j) {
        const std::size_t s = sequence_[static_cast<std::size_t>(j)];
        return s > target_sequence ? s - target_sequence : target_sequence - s;
      };
      for (const Eigen::Index j : impl_->index.within(corner_m, tolerance_m_)) {
        if (gap(j) < gap(chosen) || (gap(j) == gap(chosen) && j < chosen)) chosen = j;
      }
    }
    out.fiducial[corner] = chosen;
    out.weight[corner] = 0.125;
  }
  out.size = 8;
  return out;
}

std::string OctupletStencils::describe() const {
  std::ostringstream out;
  out << "octuplet, cube edge " << units::m_to_mm(cube_edge_m_) << " mm";
  return out.str();
}

}  // namespace vrreg
