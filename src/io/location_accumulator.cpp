// SPDX-License-Identifier: Apache-2.0
#include "location_accumulator.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "csv_fields.hpp"
#include "text_checks.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::io::detail {
namespace {

const char* role_name(Role role) { return to_string(role); }

std::string mm_text(const Eigen::Vector3d& p_m) {
  return "(" + format_double(units::m_to_mm(p_m.x())) + ", " +
         format_double(units::m_to_mm(p_m.y())) + ", " + format_double(units::m_to_mm(p_m.z())) +
         ") mm";
}

std::string location_name(const std::string& point, const std::optional<int>& config) {
  std::string name = "point '" + printable(point) + "'";
  if (config) name += " config " + std::to_string(*config);
  return name;
}

}  // namespace

LocationAccumulator::LocationAccumulator(std::string source, bool has_robot,
                                         double robot_tolerance_m, double joint_tolerance_rad)
    : source_(std::move(source)),
      has_robot_(has_robot),
      robot_tolerance_m_(robot_tolerance_m),
      joint_tolerance_rad_(joint_tolerance_rad) {}

void LocationAccumulator::check_point(const PointEntry& entry, const MeasurementRow& row,
                                      std::size_t line) const {
  if (entry.role != row.role) {
    throw FileError(source_, line,
                    location_name(key_, std::nullopt) + " has role " + role_name(row.role) +
                        " here but " + role_name(entry.role) + " on line " +
                        std::to_string(entry.first_line));
  }
  if (has_robot_ && (row.robot_m - entry.robot_m).cwiseAbs().maxCoeff() > robot_tolerance_m_) {
    throw FileError(source_, line,
                    location_name(key_, std::nullopt) + " has robot position " +
                        mm_text(row.robot_m) + " here but " + mm_text(entry.robot_m) + " on line " +
                        std::to_string(entry.first_line));
  }
}

void LocationAccumulator::check_joints(const Location& location, const MeasurementRow& row,
                                       std::size_t line) const {
  for (std::size_t k = 0; k < row.q_rad.size(); ++k) {
    if (std::abs(row.q_rad[k] - location.q_rad[k]) > joint_tolerance_rad_) {
      throw FileError(source_, line,
                      location_name(key_, row.config) + " has q" + std::to_string(k + 1) + " = " +
                          format_double(row.q_rad[k]) + " rad here but " +
                          format_double(location.q_rad[k]) + " rad on line " +
                          std::to_string(location.source_line));
    }
  }
  if (row.q_robot_marker && location.q_robot_marker) {
    const double angle_rad = row.q_robot_marker->angularDistance(*location.q_robot_marker);
    if (angle_rad > joint_tolerance_rad_) {
      throw FileError(source_, line,
                      location_name(key_, row.config) + " has a commanded orientation (robot_q) " +
                          format_double(angle_rad) + " rad from the one on line " +
                          std::to_string(location.source_line));
    }
  }
}

void LocationAccumulator::add(const MeasurementRow& row, std::size_t line) {
  ++rows_;
  key_.assign(row.point);
  auto [it, new_point] = points_.try_emplace(key_);
  PointEntry& entry = it->second;
  if (new_point) {
    entry.role = row.role;
    entry.robot_m = row.robot_m;
    entry.first_line = line;
  } else {
    check_point(entry, row, line);
  }
  std::size_t index = locations_.size();
  const std::pair<std::optional<int>, std::optional<int>> which{row.config, row.visit};
  for (const auto& [config_visit, location_index] : entry.locations) {
    if (config_visit == which) index = location_index;
  }
  if (index == locations_.size()) {
    entry.locations.emplace_back(which, index);
    Location& location = locations_.emplace_back();
    location.point = key_;
    location.role = row.role;
    location.config = row.config;
    location.visit = row.visit;
    location.has_robot = has_robot_;
    location.robot_m = row.robot_m;
    location.q_rad = row.q_rad;
    location.approach_sign = row.approach_sign;
    location.q_robot_marker = row.q_robot_marker;
    location.source_line = line;
  } else {
    check_joints(locations_[index], row, line);
    // Readings of one location that arrived from different sides leave that joint unknown.
    std::vector<double>& sign = locations_[index].approach_sign;
    for (std::size_t k = 0; k < sign.size() && k < row.approach_sign.size(); ++k) {
      if (sign[k] != row.approach_sign[k]) sign[k] = 0.0;
    }
  }
  // Welford: running mean and per-axis sum of squared deviations from it.
  Location& location = locations_[index];
  location.n_readings += 1;
  const Eigen::Vector3d delta = row.sensor_m - location.sensor_m;
  location.sensor_m += delta / static_cast<double>(location.n_readings);
  location.sensor_sq_dev_m2 += delta.cwiseProduct(row.sensor_m - location.sensor_m);
  if (row.q_sensor_marker) {
    if (orientation_sums_.size() <= index) orientation_sums_.resize(index + 1, Eigen::Matrix4d::Zero());
    if (!location.q_sensor_marker) location.q_sensor_marker = row.q_sensor_marker;
    const Eigen::Vector4d q = row.q_sensor_marker->coeffs();
    orientation_sums_[index] += q * q.transpose();
  }
}

// The mean orientation of the repeats: the eigenvector of the largest eigenvalue of sum q q'
// (Markley et al. 2007, the rotation minimising the summed squared chordal distances); q and -q
// count alike, so no sign alignment is needed. The sign of the first reading is kept.
std::vector<Location> LocationAccumulator::take() {
  for (std::size_t i = 0; i < orientation_sums_.size() && i < locations_.size(); ++i) {
    Location& location = locations_[i];
    if (!location.q_sensor_marker || location.n_readings < 2) continue;
    const QuaternionMean mean =
        quaternion_mean(orientation_sums_[i], location.n_readings, *location.q_sensor_marker);
    location.q_sensor_marker = mean.mean;
    location.orientation_sq_dev_rad2 = mean.sq_dev_rad2;
  }
  orientation_sums_.clear();
  return std::move(locations_);
}

}  // namespace vrreg::io::detail
