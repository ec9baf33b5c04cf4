// SPDX-License-Identifier: Apache-2.0
#include "base_cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <vector>
#include <numbers>

namespace vrreg::detail {
namespace {

constexpr double kMinRadiusFraction = 0.2;
constexpr double kMinGapRad = 60.0 / 180.0 * std::numbers::pi;

double wrapped(double angle_rad) {
  return std::remainder(angle_rad, 2.0 * std::numbers::pi);  // in [-pi, pi]
}

}  // namespace

std::optional<BaseCylinder> BaseCylinder::fit(const ConstPoints3Ref& robot_m) {
  const Eigen::Index n = robot_m.cols();
  if (n == 0) return std::nullopt;
  std::vector<double> azimuths(static_cast<std::size_t>(n));
  double radius_sum_m = 0.0;
  for (Eigen::Index j = 0; j < n; ++j) {
    radius_sum_m += robot_m.col(j).head<2>().norm();
    azimuths[static_cast<std::size_t>(j)] = std::atan2(robot_m(1, j), robot_m(0, j));
  }
  const double mean_radius_m = radius_sum_m / static_cast<double>(n);
  if (!(mean_radius_m > 0.0)) return std::nullopt;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (robot_m.col(j).head<2>().norm() < kMinRadiusFraction * mean_radius_m) return std::nullopt;
  }
  // The cut goes in the middle of the widest empty sector, the reference azimuth opposite it.
  std::sort(azimuths.begin(), azimuths.end());
  double widest_gap_rad = azimuths.front() + 2.0 * std::numbers::pi - azimuths.back();
  double gap_end_rad = azimuths.front();
  for (std::size_t k = 1; k < azimuths.size(); ++k) {
    if (azimuths[k] - azimuths[k - 1] > widest_gap_rad) {
      widest_gap_rad = azimuths[k] - azimuths[k - 1];
      gap_end_rad = azimuths[k];
    }
  }
  if (widest_gap_rad < kMinGapRad) return std::nullopt;
  const double span_rad = 2.0 * std::numbers::pi - widest_gap_rad;
  return BaseCylinder(mean_radius_m, wrapped(gap_end_rad + 0.5 * span_rad));
}

Points3 BaseCylinder::coordinates(const ConstPoints3Ref& robot_m) const {
  Points3 out(3, robot_m.cols());
  for (Eigen::Index j = 0; j < robot_m.cols(); ++j) {
    const double azimuth = wrapped(std::atan2(robot_m(1, j), robot_m(0, j)) - reference_azimuth_rad_);
    out.col(j) << robot_m.col(j).head<2>().norm(), mean_radius_m_ * azimuth, robot_m(2, j);
  }
  return out;
}

Points3 BaseCylinder::to_local(const ConstPoints3Ref& robot_m, const ConstPoints3Ref& v) const {
  Points3 out(3, v.cols());
  for (Eigen::Index j = 0; j < v.cols(); ++j) {
    const double azimuth = std::atan2(robot_m(1, j), robot_m(0, j));
    const double c = std::cos(azimuth);
    const double s = std::sin(azimuth);
    out.col(j) << c * v(0, j) + s * v(1, j), -s * v(0, j) + c * v(1, j), v(2, j);
  }
  return out;
}

Points3 BaseCylinder::from_local(const ConstPoints3Ref& robot_m,
                                 const ConstPoints3Ref& v_local) const {
  Points3 out(3, v_local.cols());
  for (Eigen::Index j = 0; j < v_local.cols(); ++j) {
    const double azimuth = std::atan2(robot_m(1, j), robot_m(0, j));
    const double c = std::cos(azimuth);
    const double s = std::sin(azimuth);
    out.col(j) << c * v_local(0, j) - s * v_local(1, j), s * v_local(0, j) + c * v_local(1, j),
        v_local(2, j);
  }
  return out;
}

}  // namespace vrreg::detail
