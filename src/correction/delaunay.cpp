// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/delaunay.hpp"

#include <libqhull_r/libqhull_r.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "tet_mesh.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

/// Collects qhull's messages in memory (the library never writes to files or the console).
class MessageBuffer {
 public:
  MessageBuffer() : file_(open_memstream(&data_, &size_)) {}
  ~MessageBuffer() {
    if (file_ != nullptr) std::fclose(file_);
    std::free(data_);
  }
  MessageBuffer(const MessageBuffer&) = delete;
  MessageBuffer& operator=(const MessageBuffer&) = delete;
  [[nodiscard]] FILE* file() const { return file_; }
  /// The first line written so far.
  [[nodiscard]] std::string first_line() {
    if (file_ == nullptr) return "qhull failed";
    std::fflush(file_);
    std::string text(data_ == nullptr ? "" : data_, size_);
    const auto start = text.find_first_not_of(" \n");
    if (start == std::string::npos) return "qhull failed";
    return text.substr(start, text.find('\n', start) - start);
  }

 private:
  char* data_ = nullptr;
  std::size_t size_ = 0;
  FILE* file_ = nullptr;
};

/// Owns a qhull instance and frees all of its memory.
class Qhull {
 public:
  explicit Qhull(FILE* errfile) : qh_(std::make_unique<qhT>()) { qh_zero(qh_.get(), errfile); }
  ~Qhull() {
    int curlong = 0;
    int totlong = 0;
    qh_freeqhull(qh_.get(), !qh_ALL);
    qh_memfreeshort(qh_.get(), &curlong, &totlong);
  }
  Qhull(const Qhull&) = delete;
  Qhull& operator=(const Qhull&) = delete;
  [[nodiscard]] qhT* get() const { return qh_.get(); }

 private:
  std::unique_ptr<qhT> qh_;
};

/// Qhull run on `coords` (x, y, z per point) with `options`; throws "`what` failed: ..." with
/// qhull's first message. qhull keeps pointers into the coordinates: they must outlive it.
class QhullRun {
 public:
  QhullRun(std::vector<coordT>& coords, std::string options, const std::string& what)
      : qhull_(messages_.file()) {
    const int exitcode =
        qh_new_qhull(qhull_.get(), 3, static_cast<int>(coords.size() / 3), coords.data(), False,
                     options.data(), nullptr, messages_.file());
    VRREG_THROW_UNLESS(exitcode == 0, what << " failed: " << messages_.first_line());
  }
  [[nodiscard]] qhT* get() const { return qhull_.get(); }

 private:
  MessageBuffer messages_;
  Qhull qhull_;
};

}  // namespace

Tetrahedralization delaunay_tetrahedralization(const ConstPoints3Ref& points_m) {
  const Eigen::Index n = points_m.cols();
  VRREG_THROW_UNLESS(n >= 4, "a Delaunay tetrahedralization needs at least 4 fiducials, got " << n);
  VRREG_THROW_UNLESS(points_m.allFinite(), "Delaunay tetrahedralization: non-finite coordinates");
  const Eigen::Vector3d centroid_m = points_m.rowwise().mean();
  const Points3 centred_m = points_m.colwise() - centroid_m;
  const Eigen::Vector3d singular =
      Eigen::JacobiSVD<Eigen::Matrix3d>(centred_m * centred_m.transpose()).singularValues();
  VRREG_THROW_UNLESS(singular(2) > 1e-18 * singular(0) && singular(0) > 0.0,
                     "the " << n << " fiducials are coplanar (or collinear): scattered "
                            << "interpolation needs fiducials that span a volume");

  // On a lattice the Delaunay tetrahedralization is not unique (8 co-spherical corners per cube)
  // and qhull's choice follows the input order: the points go in sorted, so that the same
  // fiducials give the same tetrahedra whatever order they were listed in.
  std::vector<Eigen::Index> sorted(static_cast<std::size_t>(n));
  std::iota(sorted.begin(), sorted.end(), Eigen::Index{0});
  std::sort(sorted.begin(), sorted.end(), [&points_m](Eigen::Index a, Eigen::Index b) {
    return std::make_tuple(points_m(0, a), points_m(1, a), points_m(2, a), a) <
           std::make_tuple(points_m(0, b), points_m(1, b), points_m(2, b), b);
  });
  // qhull keeps pointers into the coordinates: they live until the Qhull object is gone.
  std::vector<coordT> coords(static_cast<std::size_t>(3 * n));
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    for (int a = 0; a < 3; ++a) coords[3 * i + static_cast<std::size_t>(a)] = points_m(a, sorted[i]);
  }
  const QhullRun qhull(coords, "qhull d Qbb Qc Qz Q12 Qt",
                       "Delaunay tetrahedralization of " + std::to_string(n) + " fiducials");
  qhT* qh = qhull.get();

  std::vector<Eigen::Index> tet_of_facet(static_cast<std::size_t>(qh->facet_id) + 1, -1);
  Tetrahedralization out;
  facetT* facet = nullptr;
  FORALLfacets {
    if (facet->upperdelaunay || qh_setsize(qh, facet->vertices) != 4) continue;
    std::array<Eigen::Index, 4> vertices{};
    bool valid = true;
    for (int k = 0; k < 4; ++k) {
      const auto* vertex = static_cast<vertexT*>(SETelem_(facet->vertices, k));
      const int id = qh_pointid(qh, vertex->point);
      valid = valid && id >= 0 && id < n;
      vertices[static_cast<std::size_t>(k)] = valid ? sorted[static_cast<std::size_t>(id)] : -1;
    }
    if (!valid) continue;
    tet_of_facet[facet->id] = static_cast<Eigen::Index>(out.vertices.size());
    out.vertices.push_back(vertices);
  }
  out.neighbours.resize(out.vertices.size());
  FORALLfacets {
    const Eigen::Index tet = tet_of_facet[facet->id];
    if (tet < 0) continue;
    // Simplicial facets ('Qt'): neighbour k is opposite vertex k.
    for (int k = 0; k < 4; ++k) {
      const auto* neighbour = static_cast<facetT*>(SETelem_(facet->neighbors, k));
      out.neighbours[static_cast<std::size_t>(tet)][static_cast<std::size_t>(k)] =
          neighbour == nullptr ? -1 : tet_of_facet[neighbour->id];
    }
  }
  VRREG_THROW_UNLESS(!out.vertices.empty(),
                     "Delaunay tetrahedralization of " << n << " fiducials gave no tetrahedra");
  return out;
}

namespace detail {

std::vector<HullPlane> convex_hull_planes(const ConstPoints3Ref& points_m) {
  const Eigen::Index n = points_m.cols();
  VRREG_THROW_UNLESS(n >= 4 && points_m.allFinite(),
                     "the convex hull needs at least 4 finite fiducials, got " << n);
  std::vector<coordT> coords(static_cast<std::size_t>(3 * n));
  for (Eigen::Index j = 0; j < n; ++j) {
    for (int a = 0; a < 3; ++a) coords[static_cast<std::size_t>(3 * j + a)] = points_m(a, j);
  }
  const QhullRun qhull(coords, "qhull", "the convex hull of " + std::to_string(n) + " fiducials");
  qhT* qh = qhull.get();
  std::vector<HullPlane> out;
  facetT* facet = nullptr;
  FORALLfacets {
    HullPlane plane;
    plane.normal_out = Eigen::Vector3d(facet->normal[0], facet->normal[1], facet->normal[2]);
    plane.offset_m = -facet->offset;  // qhull: normal . x + offset > 0 outside
    out.push_back(plane);
  }
  return out;
}

}  // namespace detail
}  // namespace vrreg
