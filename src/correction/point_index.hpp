// SPDX-License-Identifier: Apache-2.0
#pragma once
// A kd-tree (nanoflann) over a fixed set of points: nearest neighbour and radius queries [m].
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg::detail {

/// Nearest-neighbour index over a copy of `points_m`, one column a point.
class PointIndex {
 public:
  explicit PointIndex(const ConstPoints3Ref& points_m);
  ~PointIndex();
  PointIndex(PointIndex&&) noexcept;
  PointIndex& operator=(PointIndex&&) noexcept;
  PointIndex(const PointIndex&) = delete;
  PointIndex& operator=(const PointIndex&) = delete;

  /// Column of the point nearest to `query_m` (the index must not be empty).
  [[nodiscard]] Eigen::Index nearest(const Eigen::Vector3d& query_m) const;
  /// Columns of the min(k, size) points nearest to `query_m`, nearest first.
  [[nodiscard]] std::vector<Eigen::Index> nearest_k(const Eigen::Vector3d& query_m,
                                                    std::size_t k) const;
  /// Columns of all points within `radius_m` of `query_m`, nearest first.
  [[nodiscard]] std::vector<Eigen::Index> within(const Eigen::Vector3d& query_m,
                                                 double radius_m) const;
  /// The first pair (j, k), j < k, of points closer than `tolerance_m`, if any.
  [[nodiscard]] std::optional<std::pair<Eigen::Index, Eigen::Index>> duplicate(
      double tolerance_m) const;
  [[nodiscard]] const Points3& points() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vrreg::detail
