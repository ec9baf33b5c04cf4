// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/corner_candidates.hpp"

#include <algorithm>
#include <cmath>

#include "point_index.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg {
namespace {

Eigen::Vector3d corner_offset(std::size_t corner, const Eigen::Vector3d& lo,
                              const Eigen::Vector3d& hi) {
  return {(corner & 1U) != 0 ? hi.x() : lo.x(), (corner & 2U) != 0 ? hi.y() : lo.y(),
          (corner & 4U) != 0 ? hi.z() : lo.z()};
}

}  // namespace

struct CornerCandidates::Impl {
  explicit Impl(const ConstPoints3Ref& points_m) : index(points_m) {}
  detail::PointIndex index;
};

CornerCandidates::CornerCandidates(const ConstPoints3Ref& fiducials_robot_m, double tolerance_m)
    : tolerance_m_(tolerance_m) {
  VRREG_THROW_UNLESS(std::isfinite(tolerance_m) && tolerance_m > 0.0,
                     "corner match tolerance must be > 0, got " << tolerance_m << " m");
  VRREG_THROW_UNLESS(fiducials_robot_m.cols() > 0, "no fiducials to find corners among");
  VRREG_THROW_UNLESS(fiducials_robot_m.allFinite(), "non-finite fiducial nominal positions");
  impl_ = std::make_unique<Impl>(fiducials_robot_m);
}

CornerCandidates::~CornerCandidates() = default;
CornerCandidates::CornerCandidates(CornerCandidates&&) noexcept = default;
CornerCandidates& CornerCandidates::operator=(CornerCandidates&&) noexcept = default;

const Points3& CornerCandidates::positions_m() const { return impl_->index.points(); }

std::vector<Eigen::Index> CornerCandidates::at(const Eigen::Vector3d& position_m) const {
  std::vector<Eigen::Index> out = impl_->index.within(position_m, tolerance_m_);
  std::sort(out.begin(), out.end());
  return out;
}

CornerFiducials CornerCandidates::octuplet(const Eigen::Vector3d& target_robot_nominal_m,
                                           double cube_edge_m) const {
  VRREG_THROW_UNLESS(std::isfinite(cube_edge_m) && cube_edge_m > 4.0 * tolerance_m_,
                     "octuplet cube edge must be > 4 x the match tolerance (got "
                         << units::m_to_mm(cube_edge_m) << " mm): set `cube_edge`");
  const Eigen::Vector3d half = Eigen::Vector3d::Constant(0.5 * cube_edge_m);
  CornerFiducials out;
  for (std::size_t corner = 0; corner < 8; ++corner) {
    out[corner] =
        at(corner_offset(corner, target_robot_nominal_m - half, target_robot_nominal_m + half));
  }
  return out;
}

CornerFiducials CornerCandidates::volume_corners() const {
  const Points3& p = impl_->index.points();
  const Eigen::Vector3d lo = p.rowwise().minCoeff();
  const Eigen::Vector3d hi = p.rowwise().maxCoeff();
  CornerFiducials out;
  std::array<Eigen::Index, 8> nearest{};
  for (std::size_t corner = 0; corner < 8; ++corner) {
    nearest[corner] = impl_->index.nearest(corner_offset(corner, lo, hi));
    for (std::size_t other = 0; other < corner; ++other) {
      VRREG_THROW_UNLESS((p.col(nearest[other]) - p.col(nearest[corner])).norm() > tolerance_m_,
                         "the fiducials span no volume: corners "
                             << other << " and " << corner << " of their bounding box share the "
                             << "nominal position (" << units::m_to_mm(p(0, nearest[corner]))
                             << ", " << units::m_to_mm(p(1, nearest[corner])) << ", "
                             << units::m_to_mm(p(2, nearest[corner])) << ") mm");
    }
    out[corner] = at(p.col(nearest[corner]));
  }
  return out;
}

}  // namespace vrreg
