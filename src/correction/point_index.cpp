// SPDX-License-Identifier: Apache-2.0
#include "point_index.hpp"

#include <algorithm>
#include <cstddef>
#include <nanoflann.hpp>

namespace vrreg::detail {
namespace point_index {

/// nanoflann dataset adaptor over the columns of a Points3.
struct Cloud {
  Points3 points;
  [[nodiscard]] std::size_t kdtree_get_point_count() const {
    return static_cast<std::size_t>(points.cols());
  }
  [[nodiscard]] double kdtree_get_pt(std::size_t index, std::size_t axis) const {
    return points(static_cast<Eigen::Index>(axis), static_cast<Eigen::Index>(index));
  }
  template <class Box>
  bool kdtree_get_bbox(Box& /*box*/) const {
    return false;
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud,
                                                 3, std::size_t>;

}  // namespace point_index

struct PointIndex::Impl {
  using Cloud = point_index::Cloud;
  using Tree = point_index::Tree;
  explicit Impl(const ConstPoints3Ref& points_m)
      : cloud{Points3(points_m)}, tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {
    tree.buildIndex();
  }
  Cloud cloud;
  Tree tree;
};

PointIndex::PointIndex(const ConstPoints3Ref& points_m) : impl_(std::make_unique<Impl>(points_m)) {}
PointIndex::~PointIndex() = default;
PointIndex::PointIndex(PointIndex&&) noexcept = default;
PointIndex& PointIndex::operator=(PointIndex&&) noexcept = default;

Eigen::Index PointIndex::nearest(const Eigen::Vector3d& query_m) const {
  std::size_t index = 0;
  double distance_sq = 0.0;
  impl_->tree.knnSearch(query_m.data(), 1, &index, &distance_sq);
  return static_cast<Eigen::Index>(index);
}

std::vector<Eigen::Index> PointIndex::nearest_k(const Eigen::Vector3d& query_m,
                                                std::size_t k) const {
  k = std::min(k, static_cast<std::size_t>(impl_->cloud.points.cols()));
  std::vector<std::size_t> index(k);
  std::vector<double> distance_sq(k);
  k = impl_->tree.knnSearch(query_m.data(), k, index.data(), distance_sq.data());
  return {index.begin(), index.begin() + static_cast<std::ptrdiff_t>(k)};
}

std::vector<Eigen::Index> PointIndex::within(const Eigen::Vector3d& query_m,
                                             double radius_m) const {
  std::vector<std::pair<std::size_t, double>> matches;
  // L2_Simple_Adaptor works with squared distances.
  impl_->tree.radiusSearch(query_m.data(), radius_m * radius_m, matches,
                           nanoflann::SearchParams(32, 0.0F, true));
  std::vector<Eigen::Index> out;
  out.reserve(matches.size());
  for (const auto& match : matches) out.push_back(static_cast<Eigen::Index>(match.first));
  return out;
}

std::optional<std::pair<Eigen::Index, Eigen::Index>> PointIndex::duplicate(
    double tolerance_m) const {
  const Points3& points = impl_->cloud.points;
  for (Eigen::Index j = 0; j < points.cols(); ++j) {
    for (const Eigen::Index k : within(points.col(j), tolerance_m)) {
      if (k > j) return std::make_pair(j, k);
    }
  }
  return std::nullopt;
}

const Points3& PointIndex::points() const { return impl_->cloud.points; }

}  // namespace vrreg::detail
