// SPDX-License-Identifier: Apache-2.0
// Where in the volume a subset of targets lies, in words (paper section 5.1: "three out of four
// points where RRBC failed for d_min are located on the lowest layer of targets").
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "vrreg/core/format.hpp"
#include "vrreg/report/cell_report.hpp"

namespace vrreg::report {
namespace {

constexpr double kLayerToleranceM = 0.5e-3;  // targets within 0.5 mm in z share a layer

std::string mm1(double metres) { return format_mm(metres, 1); }

struct Bucket {
  std::string name;  // "on the lowest layer (z = 175.0 mm)"
  int count = 0;
};

// Layers: the distinct z values (within the tolerance), lowest first.
std::vector<double> layers_of(const Points3& p) {
  std::vector<double> z;
  for (Eigen::Index k = 0; k < p.cols(); ++k) z.push_back(p(2, k));
  std::sort(z.begin(), z.end());
  std::vector<double> layers;
  for (double v : z) {
    if (layers.empty() || v - layers.back() > kLayerToleranceM) layers.push_back(v);
  }
  return layers;
}

std::string join_buckets(std::vector<Bucket> buckets, int total) {
  std::stable_sort(buckets.begin(), buckets.end(),
                   [](const Bucket& a, const Bucket& b) { return a.count > b.count; });
  std::string out;
  for (const Bucket& b : buckets) {
    if (b.count == 0) continue;
    if (out.empty()) {
      out = std::to_string(b.count) + " of " + std::to_string(total) + " " + b.name;
    } else {
      out += ", " + std::to_string(b.count) + " " + b.name;
    }
  }
  return out;
}

}  // namespace

std::string describe_locations(const Points3& points_robot_m, const std::vector<int>& subset) {
  if (subset.empty() || points_robot_m.cols() == 0) return "";
  const int total = static_cast<int>(subset.size());
  const Eigen::Index n = points_robot_m.cols();
  const std::vector<double> layers = layers_of(points_robot_m);
  const auto n_layers = static_cast<Eigen::Index>(layers.size());
  std::vector<Bucket> buckets;
  if (n_layers >= 2 && n_layers <= std::max<Eigen::Index>(2, n / 3)) {
    buckets = {{"on the lowest layer (z = " + mm1(layers.front()) + " mm)", 0},
               {"on the top layer (z = " + mm1(layers.back()) + " mm)", 0},
               {n_layers == 3 ? "on the middle layer (z = " + mm1(layers[1]) + " mm)"
                              : "on the " + std::to_string(n_layers - 2) + " middle layers",
                0}};
    if (n_layers == 2) buckets.pop_back();
    for (int k : subset) {
      const double z = points_robot_m(2, k);
      const int b = z - layers.front() <= kLayerToleranceM  ? 0
                    : layers.back() - z <= kLayerToleranceM ? 1
                                                            : 2;
      ++buckets[static_cast<std::size_t>(b)].count;
    }
  } else {  // scattered (or one layer): thirds of the z range
    const double lo = points_robot_m.row(2).minCoeff();
    const double hi = points_robot_m.row(2).maxCoeff();
    const double third = (hi - lo) / 3.0;
    if (third <= kLayerToleranceM) {
      buckets = {{"in the one layer of targets (z = " + mm1(lo) + " mm)", total}};
    } else {
      buckets = {{"in the lowest third (z < " + mm1(lo + third) + " mm)", 0},
                 {"in the top third (z > " + mm1(hi - third) + " mm)", 0},
                 {"in the middle third", 0}};
      for (int k : subset) {
        const double z = points_robot_m(2, k);
        ++buckets[z < lo + third ? 0 : z > hi - third ? 1 : 2].count;
      }
    }
  }
  std::string out = join_buckets(buckets, total);

  // On the boundary of the targets' bounding box: any axis at its minimum or maximum.
  const Eigen::Vector3d lo = points_robot_m.rowwise().minCoeff();
  const Eigen::Vector3d hi = points_robot_m.rowwise().maxCoeff();
  auto on_boundary = [&](Eigen::Index k) {
    for (int a = 0; a < 3; ++a) {
      if (hi[a] - lo[a] <= 2 * kLayerToleranceM) continue;  // flat axis: no boundary in it
      const double v = points_robot_m(a, k);
      if (v - lo[a] <= kLayerToleranceM || hi[a] - v <= kLayerToleranceM) return true;
    }
    return false;
  };
  int all_on = 0;
  for (Eigen::Index k = 0; k < n; ++k) all_on += on_boundary(k) ? 1 : 0;
  int subset_on = 0;
  for (int k : subset) subset_on += on_boundary(k) ? 1 : 0;
  if (all_on > 0 && all_on < n) {
    const int share = static_cast<int>(100.0 * all_on / static_cast<double>(n) + 0.5);
    out += "; " + std::to_string(subset_on) + " of " + std::to_string(total) +
           " on the boundary of the targets' volume (which holds " + std::to_string(share) +
           " % of all targets)";
  }
  return out;
}

}  // namespace vrreg::report
