// SPDX-License-Identifier: Apache-2.0
// Barycentric RRBC weights in the Delaunay tetrahedron holding the registered target (Eq. 7) as a
// correction method. The tetrahedralization is not saved but rebuilt on restore: qhull is
// deterministic (the same stencils), fast at cell sizes, and the tetrahedra would outweigh the
// rest of the model file several times.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "method_support.hpp"
#include "point_index.hpp"
#include "tet_mesh.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/correction/scattered.hpp"

namespace vrreg::detail {
namespace {

// A large cell's Delaunay tetrahedron, found among the target's nearest fiducials: the
// tetrahedralization of all 10^5 takes qhull 7-14 s and 0.5 GiB, rebuilt by every command that
// reads the model, while a target needs one tetrahedron. A tetrahedron of the Delaunay
// tetrahedralization of a subset whose circumsphere holds no other fiducial of the whole set (a
// kd-tree radius query) is one of the whole set's. So the neighbourhood grows (x4) until that
// holds, and a target outside the subset's hull is outside the fiducials' hull only if it is
// beyond one of their hull's planes. On a lattice (co-spherical corners) the tetrahedralization
// is not unique and either choice is a Delaunay one with the same linear precision.
class LocalDelaunay {
 public:
  LocalDelaunay(const ConstPoints3Ref& fiducials_robot_m, double tolerance_m)
      : index_(fiducials_robot_m),
        hull_(convex_hull_planes(fiducials_robot_m)),
        tolerance_m_(tolerance_m) {}

  [[nodiscard]] Stencil stencil(const Eigen::Vector3d& q_m) const {
    const Points3& points_m = index_.points();
    const auto n = static_cast<std::size_t>(points_m.cols());
    for (std::size_t k = std::min(kFirstNeighbours, n);; k = std::min(4 * k, n)) {
      const bool last = k == n || k >= kMaxNeighbours;
      const std::vector<Eigen::Index> near = index_.nearest_k(q_m, k);
      Points3 local_m(3, static_cast<Eigen::Index>(near.size()));
      for (std::size_t i = 0; i < near.size(); ++i)
        local_m.col(static_cast<Eigen::Index>(i)) = points_m.col(near[i]);
      std::optional<Stencil> found;
      try {
        found = ScatteredStencils(local_m, tolerance_m_).stencil(q_m);
      } catch (const InputError&) {  // a flat neighbourhood (few fiducials in a plane): widen
        if (last) throw;
        continue;
      }
      if (found->status == StencilStatus::kOk) {
        for (int c = 0; c < found->size; ++c) {
          found->fiducial[static_cast<std::size_t>(c)] =
              near[static_cast<std::size_t>(found->fiducial[static_cast<std::size_t>(c)])];
        }
        // Past kMaxNeighbours (never seen on lattices or jittered ones) the subset's
        // tetrahedron is kept: still a tetrahedron of fiducials around the target.
        if (last || empty_sphere(*found)) return *found;
      } else if (last || outside_hull(q_m)) {
        return *found;
      }
    }
  }

  [[nodiscard]] Eigen::Index size() const { return index_.points().cols(); }

 private:
  static constexpr std::size_t kFirstNeighbours = 64;
  static constexpr std::size_t kMaxNeighbours = 4096;
  // Fiducials this close to the sphere (relative) are on it: co-spherical lattice corners.
  static constexpr double kOnSphere = 1e-9;

  // Whether no fiducial but the tetrahedron's own lies inside its circumsphere.
  [[nodiscard]] bool empty_sphere(const Stencil& s) const {
    const Points3& p = index_.points();
    const Eigen::Vector3d p0 = p.col(s.fiducial[0]);
    Eigen::Matrix3d a;
    Eigen::Vector3d b;
    for (int r = 0; r < 3; ++r) {
      const Eigen::Vector3d e = p.col(s.fiducial[static_cast<std::size_t>(r) + 1]) - p0;
      a.row(r) = 2.0 * e.transpose();
      b(r) = e.squaredNorm();
    }
    const Eigen::Vector3d centre_m = p0 + a.partialPivLu().solve(b);
    const double radius_m = (centre_m - p0).norm();
    if (!std::isfinite(radius_m)) return false;
    for (const Eigen::Index j : index_.within(centre_m, radius_m * (1.0 - kOnSphere))) {
      if (std::find(s.fiducial.begin(), s.fiducial.begin() + s.size, j) ==
          s.fiducial.begin() + s.size)
        return false;
    }
    return true;
  }

  [[nodiscard]] bool outside_hull(const Eigen::Vector3d& q_m) const {
    return std::any_of(hull_.begin(), hull_.end(), [&](const HullPlane& plane) {
      return plane.distance_m(q_m) > tolerance_m_;
    });
  }

  PointIndex index_;
  std::vector<HullPlane> hull_;
  double tolerance_m_;
};

// The RMS distance of the fiducials' nominal positions from their best-fitting plane [m], and
// the largest RMS spread along a principal axis [m].
std::pair<double, double> thickness_and_extent_m(const CorrectorData& data) {
  const Points3 centred =
      data.fiducials_robot_m.colwise() - data.fiducials_robot_m.rowwise().mean();
  const Eigen::Vector3d variance_m2 =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(centred * centred.transpose() /
                                                     static_cast<double>(data.size()))
          .eigenvalues();
  return {std::sqrt(std::max(variance_m2(0), 0.0)), std::sqrt(std::max(variance_m2(2), 0.0))};
}

// Within the match tolerance of a plane (or a line): no tetrahedron has a volume.
bool is_flat(const CorrectorData& data, const MethodSettings& settings) {
  const auto [thickness_m, extent_m] = thickness_and_extent_m(data);
  return thickness_m <= settings.match_tolerance_m || thickness_m <= 1e-9 * extent_m;
}

class ScatteredMethod final : public FittedMethod {
 public:
  ScatteredMethod(const CorrectorData& data, const MethodSettings& settings)
      : corrections_sensor_m_(data.corrections_sensor_m) {
    if (is_flat(data, settings)) {
      // Registration needs three points off a line; interpolation in 3D needs a volume. A flat
      // layout is answered, every point uncorrected with the reason, not refused.
      std::ostringstream why;
      why << "none: the " << data.size()
          << " fiducials lie in a plane or on a line (RMS distance from their plane "
          << std::setprecision(3) << units::m_to_mm(thickness_and_extent_m(data).first)
          << " mm), no tetrahedron to interpolate in; every point is left uncorrected";
      flat_ = why.str();
    } else if (data.size() > kLargeCellFiducials) {
      local_.emplace(data.fiducials_robot_m, settings.match_tolerance_m);
    } else {
      stencils_.emplace(data.fiducials_robot_m, settings.match_tolerance_m);
    }
  }

  [[nodiscard]] InterpolationMethod method() const override {
    return InterpolationMethod::kScattered;
  }
  [[nodiscard]] std::string describe() const override {
    if (!flat_.empty()) return flat_;
    if (stencils_) return stencils_->describe();
    return "scattered, Delaunay tetrahedron among the nearest of " +
           std::to_string(local_->size()) + " fiducials (64 or more, until its circumsphere "
           "holds no other)";
  }

  void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
               MethodPredictions& out) const override {
    for (Eigen::Index i = begin; i < end; ++i) {
      Stencil& stencil = out.stencils[static_cast<std::size_t>(i)];
      const Eigen::Vector3d q_m = query.registered_robot_m.col(i);
      stencil = !flat_.empty()   ? flagged_stencil(StencilStatus::kFlatLayout)
                : stencils_      ? stencils_->stencil(q_m)
                : q_m.allFinite() ? local_->stencil(q_m)
                                  : flagged_stencil(StencilStatus::kOutsideHull);
      if (stencil.status == StencilStatus::kOk) {
        out.corrections_sensor_m.col(i) = interpolate_correction(stencil, corrections_sensor_m_);
      } else {
        out.corrections_sensor_m.col(i).setZero();
      }
    }
  }

  [[nodiscard]] MethodState save() const override { return MethodState("scattered"); }

 private:
  std::optional<ScatteredStencils> stencils_;
  std::optional<LocalDelaunay> local_;
  Points3 corrections_sensor_m_;
  std::string flat_;  ///< why a flat layout corrects nothing; empty otherwise
};

// What qhull would refuse, said before it is asked: too few fiducials, two at one position. (All
// in a plane is fitted: every point is then answered "flat layout".)
std::string scattered_unavailable(const CorrectorData& data, const MethodSettings& settings) {
  const Eigen::Index n = data.size();
  if (n < kMinCorrectableFiducials) {
    return "scattered interpolation needs at least 4 fiducials, got " + std::to_string(n);
  }
  const PointIndex index(data.fiducials_robot_m);
  if (const auto pair = index.duplicate(settings.match_tolerance_m)) {
    return "fiducials " + std::to_string(pair->first) + " and " + std::to_string(pair->second) +
           " share a nominal robot position (within " +
           std::to_string(units::m_to_mm(settings.match_tolerance_m)) +
           " mm): use one arm configuration per model";
  }
  return {};
}

FitOutcome fit_scattered(const CorrectorData& data, const MethodSettings& settings) {
  return fitted<ScatteredMethod>(data, settings);
}

std::unique_ptr<const FittedMethod> restore_scattered(const MethodState&,
                                                      const CorrectorData& data,
                                                      const MethodSettings& settings) {
  return std::make_unique<const ScatteredMethod>(data, settings);
}

}  // namespace

CorrectionMethod scattered_method() {
  return {InterpolationMethod::kScattered, false, scattered_unavailable, fit_scattered,
          restore_scattered};
}

}  // namespace vrreg::detail
