// SPDX-License-Identifier: Apache-2.0
#include "tet_mesh.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace vrreg::detail {
namespace {

constexpr double kFlatRelativeHeight = 1e-10;  // min height / longest edge below this: flat

/// The three vertices of face k (opposite vertex k).
std::array<Eigen::Vector3d, 3> face(const Points3& points_m, const std::array<Eigen::Index, 4>& v,
                                    std::size_t k) {
  std::array<Eigen::Vector3d, 3> out;
  std::size_t f = 0;
  for (std::size_t c = 0; c < 4; ++c) {
    if (c != k) out[f++] = points_m.col(v[c]);
  }
  return out;
}

TetGeometry make_geometry(const Points3& points_m, const std::array<Eigen::Index, 4>& v) {
  TetGeometry tet;
  tet.p0_m = points_m.col(v[0]);
  Eigen::Matrix3d edges;
  for (Eigen::Index c = 0; c < 3; ++c) {
    edges.col(c) = points_m.col(v[static_cast<std::size_t>(c) + 1]) - tet.p0_m;
  }
  double longest_m = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    for (std::size_t b = a + 1; b < 4; ++b) {
      longest_m = std::max(longest_m, (points_m.col(v[a]) - points_m.col(v[b])).norm());
    }
  }
  const double volume6 = std::abs(edges.determinant());
  double min_height_m = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 4; ++k) {
    const auto f = face(points_m, v, k);
    const double area2 = (f[1] - f[0]).cross(f[2] - f[0]).norm();
    min_height_m = std::min(min_height_m, area2 > 0.0 ? volume6 / area2 : 0.0);
  }
  tet.flat = !(min_height_m > kFlatRelativeHeight * longest_m);
  if (!tet.flat) tet.to_bary = edges.inverse();
  return tet;
}

/// A flat cluster (flat tetrahedra glued by faces: one plane) with a hull face lies in that hull
/// plane; the solid faces glued to it are then hull faces too, judged by the same plane.
void mark_flat_hull_faces(TetMesh& mesh) {
  const auto n_tets = mesh.tets.size();
  std::vector<std::size_t> root(n_tets);
  for (std::size_t t = 0; t < n_tets; ++t) root[t] = t;
  const auto find = [&](std::size_t t) {
    while (root[t] != t) t = root[t] = root[root[t]];
    return t;
  };
  for (std::size_t t = 0; t < n_tets; ++t) {
    if (!mesh.tets[t].flat) continue;
    for (const Eigen::Index n : mesh.topology.neighbours[t]) {
      if (n >= 0 && mesh.tets[static_cast<std::size_t>(n)].flat) {
        root[find(t)] = find(static_cast<std::size_t>(n));
      }
    }
  }
  std::vector<int> cluster_plane(n_tets, -1);
  for (std::size_t t = 0; t < n_tets; ++t) {
    if (!mesh.tets[t].flat) continue;
    for (const int plane : mesh.tets[t].hull_plane) {
      if (plane >= 0) cluster_plane[find(t)] = plane;
    }
  }
  for (std::size_t t = 0; t < n_tets; ++t) {
    if (mesh.tets[t].flat) continue;
    for (std::size_t k = 0; k < 4; ++k) {
      const Eigen::Index n = mesh.topology.neighbours[t][k];
      if (n < 0 || !mesh.tets[static_cast<std::size_t>(n)].flat) continue;
      const int plane = cluster_plane[find(static_cast<std::size_t>(n))];
      if (plane >= 0) mesh.tets[t].hull_plane[k] = plane;
    }
  }
}

}  // namespace

TetMesh make_tet_mesh(const Points3& points_m, Tetrahedralization topology) {
  TetMesh mesh;
  mesh.topology = std::move(topology);
  const Eigen::Vector3d centroid_m = points_m.rowwise().mean();  // inside the convex hull
  const auto n_tets = mesh.topology.vertices.size();
  mesh.tets.reserve(n_tets);
  mesh.incident.assign(static_cast<std::size_t>(points_m.cols()), -1);
  for (std::size_t t = 0; t < n_tets; ++t) {
    const auto& v = mesh.topology.vertices[t];
    TetGeometry tet = make_geometry(points_m, v);
    for (std::size_t k = 0; k < 4; ++k) {
      if (mesh.topology.neighbours[t][k] >= 0) continue;
      const auto f = face(points_m, v, k);
      const Eigen::Vector3d normal = (f[1] - f[0]).cross(f[2] - f[0]);
      if (!(normal.norm() > 0.0)) continue;  // a degenerate hull triangle: no plane
      HullPlane plane;
      plane.normal_out = normal.normalized();
      if (plane.normal_out.dot(centroid_m - f[0]) > 0.0) plane.normal_out = -plane.normal_out;
      plane.offset_m = plane.normal_out.dot(f[0]);
      tet.hull_plane[k] = static_cast<int>(mesh.hull.size());
      mesh.hull.push_back(plane);
    }
    if (tet.flat) {
      ++mesh.n_flat;
    } else {
      if (mesh.first_solid < 0) mesh.first_solid = static_cast<Eigen::Index>(t);
      for (const Eigen::Index p : v) {
        auto& slot = mesh.incident[static_cast<std::size_t>(p)];
        if (slot < 0) slot = static_cast<Eigen::Index>(t);
      }
    }
    mesh.tets.push_back(tet);
  }
  mark_flat_hull_faces(mesh);
  return mesh;
}

}  // namespace vrreg::detail
