// SPDX-License-Identifier: Apache-2.0
// Checks the field models share (method_support.hpp).
#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "field_basis.hpp"
#include "method_support.hpp"
#include "point_index.hpp"

namespace vrreg::detail {
namespace {

/// Joint angles further apart than this at one nominal position are another arm configuration.
constexpr double kSameConfigurationRad = 1e-3;

/// The support's margin beyond the fiducials' box, as a fraction of the layout spacing.
constexpr double kSupportMarginFraction = 0.25;

}  // namespace

double volume_spacing_m(const ConstPoints3Ref& points_m) {
  if (points_m.cols() == 0) return 0.0;
  const Eigen::Vector3d extent = points_m.rowwise().maxCoeff() - points_m.rowwise().minCoeff();
  double volume = 1.0;
  int dims = 0;
  for (int a = 0; a < 3; ++a) {
    if (extent(a) > 1e-9 * extent.maxCoeff()) {
      volume *= extent(a);
      ++dims;
    }
  }
  return dims == 0 ? 0.0 : std::pow(volume / static_cast<double>(points_m.cols()), 1.0 / dims);
}

double layout_spacing_m(const ConstPoints3Ref& points_m) {
  const Eigen::Index n = points_m.cols();
  double spacing = volume_spacing_m(points_m);
  const PointIndex index(points_m);
  std::vector<double> nearest;
  for (Eigen::Index j = 0; j < n; ++j) {
    const std::vector<Eigen::Index> two = index.nearest_k(points_m.col(j), 2);
    if (two.size() == 2) nearest.push_back((points_m.col(two[1]) - points_m.col(j)).norm());
  }
  if (!nearest.empty()) {
    std::nth_element(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(nearest.size() / 2),
                     nearest.end());
    spacing = std::max(spacing, nearest[nearest.size() / 2]);
  }
  return spacing > 0.0 ? spacing : 1e-3;
}

SupportBox field_support(const ConstPoints3Ref& fiducials_robot_m) {
  return {fiducials_robot_m.rowwise().minCoeff(), fiducials_robot_m.rowwise().maxCoeff(),
          kSupportMarginFraction * layout_spacing_m(fiducials_robot_m)};
}

std::string configuration_clash(const CorrectorData& data, double tolerance_m) {
  if (!data.has_joints()) return {};
  std::map<std::array<long long, 3>, Eigen::Index> first_at;
  for (Eigen::Index j = 0; j < data.size(); ++j) {
    std::array<long long, 3> key{};
    for (int axis = 0; axis < 3; ++axis)
      key[static_cast<std::size_t>(axis)] =
          std::llround(data.fiducials_robot_m(axis, j) / tolerance_m);
    const auto [it, inserted] = first_at.emplace(key, j);
    if (inserted) continue;
    const Eigen::Index k = it->second;
    if ((data.joints_rad.col(j) - data.joints_rad.col(k)).cwiseAbs().maxCoeff() >
        kSameConfigurationRad) {
      std::ostringstream out;
      out << "fiducials " << k << " and " << j
          << " share a nominal robot position in different arm configurations (use joint, or "
             "one model per configuration)";
      return out.str();
    }
  }
  return {};
}

std::string polynomial_unavailable(const CorrectorData& data, int degree, const char* what) {
  const int terms = trend_terms(degree);
  if (data.size() < terms + 1) {
    return std::string(what) + ": " + std::to_string(data.size()) + " fiducials, a degree-" +
           std::to_string(degree) + " polynomial needs at least " + std::to_string(terms + 1);
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(
      trend_basis(data.fiducials_robot_m, degree, trend_frame(data.fiducials_robot_m)));
  if (qr.rank() < terms) {
    return std::string(what) + ": the " + std::to_string(data.size()) +
           " fiducial positions cannot determine a degree-" + std::to_string(degree) +
           " polynomial (coplanar or collinear?)";
  }
  return {};
}

std::string coincidence_unavailable(const CorrectorData& data, const char* what) {
  const double extent_m = trend_frame(data.fiducials_robot_m).scale_m;
  const PointIndex index(data.fiducials_robot_m);
  if (const auto pair = index.duplicate(1e-9 * extent_m)) {
    return std::string(what) + ": fiducials " + std::to_string(pair->first) + " and " +
           std::to_string(pair->second) + " share a position";
  }
  return {};
}

}  // namespace vrreg::detail
