// SPDX-License-Identifier: Apache-2.0
#include "loo_stencil.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <map>

#include "point_index.hpp"

namespace vrreg::detail {
namespace {

// Fewer neighbours than this leave no redundancy for judging an affine fit (4 parameters).
constexpr std::size_t kMinNeighbours = 6;
// A prediction noisier than ~1.7x the fiducial's own noise judges nothing well (extrapolation).
constexpr double kMaxVarianceFactor = 4.0;
// Singular values below this fraction of the largest are dropped (neighbours in a plane/line).
constexpr double kRankTolerance = 1e-6;

}  // namespace

std::vector<std::vector<Eigen::Index>> group_neighbours(const ConstPoints3Ref& points_m,
                                                        const std::vector<int>& groups, int k) {
  const Eigen::Index n = points_m.cols();
  std::map<int, std::vector<Eigen::Index>> members;
  for (Eigen::Index j = 0; j < n; ++j) {
    members[groups.empty() ? 0 : groups[static_cast<std::size_t>(j)]].push_back(j);
  }
  std::vector<std::vector<Eigen::Index>> out(static_cast<std::size_t>(n));
  for (const auto& [group, columns] : members) {
    Points3 group_points(3, static_cast<Eigen::Index>(columns.size()));
    for (std::size_t i = 0; i < columns.size(); ++i) {
      group_points.col(static_cast<Eigen::Index>(i)) = points_m.col(columns[i]);
    }
    const PointIndex index(group_points);
    for (const Eigen::Index j : columns) {
      std::vector<Eigen::Index>& list = out[static_cast<std::size_t>(j)];
      for (const Eigen::Index i : index.nearest_k(points_m.col(j), static_cast<std::size_t>(k) + 1)) {
        const Eigen::Index column = columns[static_cast<std::size_t>(i)];
        if (column != j && list.size() < static_cast<std::size_t>(k)) list.push_back(column);
      }
    }
  }
  return out;
}

LooStencil affine_stencil(const ConstPoints3Ref& points_m, const Eigen::Vector3d& at_m,
                          std::vector<Eigen::Index> neighbours) {
  LooStencil out;
  out.fiducial = std::move(neighbours);
  const auto n = static_cast<Eigen::Index>(out.fiducial.size());
  if (out.fiducial.size() < kMinNeighbours) return out;
  // Design [1, (Y_k - at) / h]: the intercept of the fit is the prediction at `at`.
  double h = 0.0;
  for (const Eigen::Index k : out.fiducial) h = std::max(h, (points_m.col(k) - at_m).norm());
  if (!(h > 0.0)) return out;
  Eigen::MatrixXd a(n, 4);
  for (Eigen::Index i = 0; i < n; ++i) {
    a(i, 0) = 1.0;
    a.block<1, 3>(i, 1) =
        ((points_m.col(out.fiducial[static_cast<std::size_t>(i)]) - at_m) / h).transpose();
  }
  // w = A (A'A)^+ e1 = U S^-1 V' e1, small singular values dropped.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(4);
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    if (s(i) > kRankTolerance * s(0)) coefficients(i) = svd.matrixV()(0, i) / s(i);
  }
  const Eigen::VectorXd w = svd.matrixU() * coefficients;
  out.weight.assign(w.data(), w.data() + n);
  out.variance_factor = 1.0 + w.squaredNorm();
  out.ok = std::abs(w.sum() - 1.0) < 1e-6 && out.variance_factor <= kMaxVarianceFactor;
  return out;
}

LooStencil loo_stencil(const ConstPoints3Ref& points_m, Eigen::Index j,
                       const std::vector<Eigen::Index>& neighbours,
                       const std::vector<bool>& usable) {
  std::vector<Eigen::Index> kept;
  for (const Eigen::Index k : neighbours) {
    if (usable[static_cast<std::size_t>(k)]) kept.push_back(k);
  }
  return affine_stencil(points_m, points_m.col(j), std::move(kept));
}

}  // namespace vrreg::detail
