// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/spread_points.hpp"

#include <algorithm>
#include <limits>

#include "vrreg/core/check.hpp"

namespace vrreg::planning {

std::vector<std::size_t> spread_points(const ConstPoints3Ref& points_m, std::size_t count) {
  VRREG_THROW_UNLESS(points_m.allFinite(), "spread points: a point is not finite");
  const auto n = static_cast<std::size_t>(points_m.cols());
  count = std::min(count, n);
  std::vector<std::size_t> chosen;
  if (count == 0) return chosen;
  const Eigen::Vector3d centroid = points_m.rowwise().mean();
  // Distance of every point to the nearest chosen one (to the centroid before the first).
  Eigen::VectorXd nearest = (points_m.colwise() - centroid).colwise().squaredNorm().transpose();
  while (chosen.size() < count) {
    Eigen::Index best = 0;
    nearest.maxCoeff(&best);  // the first of equal maxima
    chosen.push_back(static_cast<std::size_t>(best));
    const Eigen::VectorXd to_best =
        (points_m.colwise() - points_m.col(best)).colwise().squaredNorm().transpose();
    nearest = nearest.cwiseMin(to_best);
    nearest(best) = -1.0;
  }
  return chosen;
}

}  // namespace vrreg::planning
