// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/local_rms.hpp"

#include <cmath>
#include <vector>

#include "point_index.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg {

Eigen::VectorXd local_rms(const ConstPoints3Ref& points_m, const Eigen::VectorXd& squared_m2,
                          const ConstPoints3Ref& queries_m, int k) {
  VRREG_THROW_UNLESS(k >= 1, "local RMS: k must be at least 1, got " << k);
  VRREG_THROW_UNLESS(squared_m2.size() == points_m.cols(),
                     "local RMS: " << squared_m2.size() << " values for " << points_m.cols()
                                   << " points");
  std::vector<Eigen::Index> known;
  for (Eigen::Index j = 0; j < squared_m2.size(); ++j) {
    if (std::isfinite(squared_m2(j))) known.push_back(j);
  }
  VRREG_THROW_UNLESS(!known.empty(), "local RMS: no point has a known error");
  Points3 known_m(3, static_cast<Eigen::Index>(known.size()));
  for (std::size_t i = 0; i < known.size(); ++i)
    known_m.col(static_cast<Eigen::Index>(i)) = points_m.col(known[i]);
  const detail::PointIndex index(known_m);
  Eigen::VectorXd out(queries_m.cols());
  for (Eigen::Index q = 0; q < queries_m.cols(); ++q) {
    const std::vector<Eigen::Index> near =
        index.nearest_k(queries_m.col(q), static_cast<std::size_t>(k));
    double sum = 0.0;
    for (const Eigen::Index i : near) sum += squared_m2(known[static_cast<std::size_t>(i)]);
    out(q) = std::sqrt(sum / static_cast<double>(near.size()));
  }
  return out;
}

}  // namespace vrreg
