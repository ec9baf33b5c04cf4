// SPDX-License-Identifier: Apache-2.0
// Point location in a Delaunay tetrahedralization by a visibility walk (move across the face
// whose barycentric coordinate is most negative), started at a tetrahedron incident to the
// nearest fiducial. Flat tetrahedra (cospherical input, e.g. grids) are stepped over; if the walk
// still gets stuck, a breadth-first search over the whole mesh decides, so the answer never
// depends on the walk. Outside the hull: beyond a hull face's plane by more than the tolerance.
#include "vrreg/correction/scattered.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <sstream>

#include "point_index.hpp"
#include "tet_mesh.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg {
namespace {

constexpr int kMaxWalkSteps = 1000;
constexpr std::size_t kMaxFlatCluster = 64;

constexpr Stencil outside_hull() {
  return Stencil{.fiducial = {}, .weight = {}, .size = 0, .status = StencilStatus::kOutsideHull};
}

/// Where a point is relative to one non-flat tetrahedron.
struct Evaluation {
  std::array<double, 4> l{};
  bool outside_hull = false;  ///< beyond one of its hull faces by more than the tolerance
  bool inside = false;        ///< within roundoff of it (or within the tolerance of its hull faces)
  int move = -1;              ///< most negative interior face with a non-flat neighbour
  double score = 0.0;         ///< min l_k over interior faces: closeness, for choosing
};

}  // namespace

struct ScatteredStencils::Impl {
  Impl(const ConstPoints3Ref& points_m, double tolerance)
      : index(points_m), tolerance_m(tolerance) {}

  detail::PointIndex index;
  double tolerance_m;
  detail::TetMesh mesh;

  [[nodiscard]] const detail::TetGeometry& tet(Eigen::Index t) const {
    return mesh.tets[static_cast<std::size_t>(t)];
  }
  [[nodiscard]] const std::array<Eigen::Index, 4>& neighbours(Eigen::Index t) const {
    return mesh.topology.neighbours[static_cast<std::size_t>(t)];
  }
  [[nodiscard]] bool beyond_hull(Eigen::Index t, const Eigen::Vector3d& q_m) const {
    for (const int plane : tet(t).hull_plane) {
      if (plane >= 0 && mesh.hull[static_cast<std::size_t>(plane)].distance_m(q_m) > tolerance_m) {
        return true;
      }
    }
    return false;
  }

  [[nodiscard]] Evaluation evaluate(Eigen::Index t, const Eigen::Vector3d& q_m) const {
    Evaluation e;
    e.l = tet(t).bary(q_m);
    e.outside_hull = beyond_hull(t, q_m);
    e.inside = !e.outside_hull;
    e.score = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < 4; ++k) {
      const Eigen::Index n = neighbours(t)[k];
      if (n < 0 || tet(t).hull_plane[k] >= 0) continue;  // a hull face: judged by its plane
      e.score = std::min(e.score, e.l[k]);
      if (e.l[k] >= -detail::kInteriorRoundoff) continue;
      e.inside = false;
      if (!tet(n).flat && (e.move < 0 || e.l[k] < e.l[static_cast<std::size_t>(e.move)])) {
        e.move = static_cast<int>(k);
      }
    }
    return e;
  }

  [[nodiscard]] Stencil make_stencil(Eigen::Index t, std::array<double, 4> l) const {
    double sum = 0.0;
    for (double& w : l) sum += (w = std::max(w, 0.0));  // clamp roundoff / hull tolerance
    Stencil out;
    out.size = 4;
    for (std::size_t k = 0; k < 4; ++k) {
      out.fiducial[k] = mesh.topology.vertices[static_cast<std::size_t>(t)][k];
      out.weight[k] = l[k] / sum;
    }
    return out;
  }

  /// From `t`, blocked by flat tetrahedra, the best solid tetrahedron across the flat cluster,
  /// on q's side of its plane (`found` if it holds q); -1 if none; `outside` if q is beyond a
  /// hull face of the cluster.
  [[nodiscard]] Eigen::Index cross_flat(Eigen::Index t, const Evaluation& e,
                                        const Eigen::Vector3d& q_m, bool& found,
                                        bool& outside) const {
    // The blocking face with the most negative coordinate defines the plane to cross.
    std::size_t face = 4;
    for (std::size_t k = 0; k < 4; ++k) {
      const Eigen::Index n = neighbours(t)[k];
      if (n >= 0 && tet(n).flat && e.l[k] < -detail::kInteriorRoundoff &&
          (face == 4 || e.l[k] < e.l[face])) {
        face = k;
      }
    }
    if (face == 4) return -1;
    const Points3& points_m = index.points();
    // l_face is an affine function vanishing on the plane and positive at t's apex: far side < 0.
    const auto far_side = [&](Eigen::Index m) {
      Eigen::Vector3d centroid_m = Eigen::Vector3d::Zero();
      for (const Eigen::Index v : mesh.topology.vertices[static_cast<std::size_t>(m)]) {
        centroid_m += 0.25 * points_m.col(v);
      }
      return tet(t).bary(centroid_m)[face] < 0.0;
    };
    std::vector<Eigen::Index> cluster{neighbours(t)[face]};
    Eigen::Index best = -1;
    double best_score = -std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < cluster.size(); ++c) {
      if (beyond_hull(cluster[c], q_m)) {
        outside = true;
        return -1;
      }
      for (const Eigen::Index m : neighbours(cluster[c])) {
        if (m < 0 || m == t) continue;
        if (tet(m).flat) {
          if (cluster.size() < kMaxFlatCluster &&
              std::find(cluster.begin(), cluster.end(), m) == cluster.end()) {
            cluster.push_back(m);
          }
          continue;
        }
        if (!far_side(m)) continue;
        const Evaluation candidate = evaluate(m, q_m);
        if (candidate.inside) {
          found = true;
          return m;
        }
        if (candidate.score > best_score) {
          best_score = candidate.score;
          best = m;
        }
      }
    }
    return best;
  }

  /// Breadth-first over the whole mesh from `start`: complete, for when the walk gives up.
  [[nodiscard]] Stencil search(Eigen::Index start, const Eigen::Vector3d& q_m) const {
    std::vector<char> seen(mesh.tets.size(), 0);
    std::deque<Eigen::Index> queue{start};
    seen[static_cast<std::size_t>(start)] = 1;
    while (!queue.empty()) {
      const Eigen::Index t = queue.front();
      queue.pop_front();
      if (beyond_hull(t, q_m)) return outside_hull();
      if (!tet(t).flat) {
        const Evaluation e = evaluate(t, q_m);
        if (e.inside) return make_stencil(t, e.l);
      }
      for (const Eigen::Index n : neighbours(t)) {
        if (n >= 0 && seen[static_cast<std::size_t>(n)] == 0) {
          seen[static_cast<std::size_t>(n)] = 1;
          queue.push_back(n);
        }
      }
    }
    return outside_hull();
  }

  [[nodiscard]] Stencil locate(const Eigen::Vector3d& q_m, LocateStats& stats) const {
    Eigen::Index t = mesh.incident[static_cast<std::size_t>(index.nearest(q_m))];
    if (t < 0) t = mesh.first_solid;
    for (; stats.steps < kMaxWalkSteps; ++stats.steps) {
      const Evaluation e = evaluate(t, q_m);
      if (e.outside_hull) return outside_hull();
      if (e.inside) return make_stencil(t, e.l);
      if (e.move >= 0) {
        t = neighbours(t)[static_cast<std::size_t>(e.move)];
        continue;
      }
      bool found = false;
      bool outside = false;
      const Eigen::Index next = cross_flat(t, e, q_m, found, outside);
      if (outside) return outside_hull();
      if (next < 0) break;
      t = next;
      if (found) return make_stencil(t, tet(t).bary(q_m));
    }
    stats.fallback = true;
    return search(t, q_m);
  }
};

ScatteredStencils::ScatteredStencils(const ConstPoints3Ref& fiducials_robot_m, double tolerance_m) {
  VRREG_THROW_UNLESS(std::isfinite(tolerance_m) && tolerance_m > 0.0,
                     "scattered interpolation needs a tolerance > 0, got " << tolerance_m << " m");
  VRREG_THROW_UNLESS(
      fiducials_robot_m.cols() >= 4,
      "scattered interpolation needs at least 4 fiducials, got " << fiducials_robot_m.cols());
  VRREG_THROW_UNLESS(fiducials_robot_m.allFinite(),
                     "scattered interpolation: non-finite fiducial coordinates");
  impl_ = std::make_unique<Impl>(fiducials_robot_m, tolerance_m);
  const auto pair = impl_->index.duplicate(tolerance_m);
  VRREG_THROW_UNLESS(!pair, "fiducials " << (pair ? pair->first : 0) << " and "
                                         << (pair ? pair->second : 0)
                                         << " share a nominal robot position (within "
                                         << units::m_to_mm(tolerance_m)
                                         << " mm): use one arm configuration per model");
  const Points3& points_m = impl_->index.points();
  impl_->mesh = detail::make_tet_mesh(points_m, delaunay_tetrahedralization(points_m));
  VRREG_THROW_UNLESS(impl_->mesh.first_solid >= 0, "the Delaunay tetrahedra of the "
                                                       << points_m.cols()
                                                       << " fiducials are all flat");
}

ScatteredStencils::~ScatteredStencils() = default;
ScatteredStencils::ScatteredStencils(ScatteredStencils&&) noexcept = default;
ScatteredStencils& ScatteredStencils::operator=(ScatteredStencils&&) noexcept = default;

Stencil ScatteredStencils::stencil(const Eigen::Vector3d& point_robot_m, LocateStats* stats) const {
  if (!point_robot_m.allFinite()) return outside_hull();
  LocateStats local;
  const Stencil out = impl_->locate(point_robot_m, local);
  if (stats != nullptr) *stats = local;
  return out;
}

std::string ScatteredStencils::describe() const {
  std::ostringstream out;
  out << "scattered, Delaunay of " << impl_->index.points().cols()
      << " fiducials: " << n_tetrahedra() << " tetrahedra (" << n_flat() << " flat)";
  return out.str();
}

std::int64_t ScatteredStencils::n_tetrahedra() const {
  return static_cast<std::int64_t>(impl_->mesh.tets.size());
}
std::int64_t ScatteredStencils::n_flat() const { return impl_->mesh.n_flat; }

}  // namespace vrreg
