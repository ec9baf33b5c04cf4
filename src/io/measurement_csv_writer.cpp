// SPDX-License-Identifier: Apache-2.0
#include "vrreg/io/measurement_csv_writer.hpp"

#include <cmath>

#include "csv_fields.hpp"
#include "text_checks.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/atomic_write.hpp"

namespace vrreg::io {
namespace {

void check_label(const std::string& point, std::size_t index) {
  VRREG_THROW_UNLESS(!point.empty(), "reading " << index << ": empty point label");
  VRREG_THROW_UNLESS(point.find_first_of(",\"\r\n") == std::string::npos && point.front() != '#' &&
                         detail::trim(point).size() == point.size(),
                     "reading " << index << ": point label '" << point
                                << "' cannot be written (comma, quote, newline, leading '#' or "
                                   "surrounding spaces)");
  const auto problem = detail::find_non_text(point);
  VRREG_THROW_UNLESS(!problem, "reading " << index << ": point label: " << *problem);
}

void append_mm(std::string& out, const Eigen::Vector3d& p_m, std::size_t index) {
  for (int axis = 0; axis < 3; ++axis) {
    VRREG_THROW_UNLESS(std::isfinite(p_m(axis)), "reading " << index << ": non-finite coordinate");
    out += ',';
    out += detail::format_double(units::m_to_mm(p_m(axis)));
  }
}

void append_quaternion(std::string& out, const Eigen::Quaterniond& q, std::size_t index) {
  VRREG_THROW_UNLESS(q.coeffs().allFinite() && std::abs(q.norm() - 1.0) <= 1e-9,
                     "reading " << index << ": an orientation that is not a unit quaternion");
  for (int k = 0; k < 4; ++k) {  // coeffs(): x, y, z, w
    out += ',';
    out += detail::format_double(q.coeffs()(k));
  }
}

void append_comments(std::string& out, const std::vector<std::string>& comments) {
  for (const std::string& comment : comments) {
    std::size_t start = 0;
    for (;;) {
      const std::size_t newline = comment.find('\n', start);
      const std::string line =
          comment.substr(start, newline == std::string::npos ? std::string::npos : newline - start);
      const auto problem = detail::find_non_text(line);
      VRREG_THROW_UNLESS(!problem, "comment line: " << *problem);
      out += "# ";
      out += line;
      out += '\n';
      if (newline == std::string::npos) break;
      start = newline + 1;
    }
  }
}

}  // namespace

std::string format_measurement_csv(const std::vector<Reading>& readings,
                                   const std::vector<std::string>& comments) {
  VRREG_THROW_UNLESS(!readings.empty(), "no readings to write");
  const Reading& first = readings.front();
  const std::size_t n_joints = first.q_rad.size();
  for (std::size_t i = 0; i < readings.size(); ++i) {
    const Reading& r = readings[i];
    check_label(r.point, i);
    VRREG_THROW_UNLESS(r.has_robot == first.has_robot,
                       "reading " << i << ": has_robot differs from reading 0");
    VRREG_THROW_UNLESS(r.config.has_value() == first.config.has_value(),
                       "reading " << i << ": config given for some readings but not all");
    VRREG_THROW_UNLESS(r.repeat.has_value() == first.repeat.has_value(),
                       "reading " << i << ": repeat given for some readings but not all");
    VRREG_THROW_UNLESS(!r.repeat || *r.repeat >= 0, "reading " << i << ": negative repeat");
    VRREG_THROW_UNLESS(r.visit.has_value() == first.visit.has_value(),
                       "reading " << i << ": visit given for some readings but not all");
    VRREG_THROW_UNLESS(!r.visit || *r.visit >= 0, "reading " << i << ": negative visit");
    VRREG_THROW_UNLESS(r.q_sensor_marker.has_value() == first.q_sensor_marker.has_value(),
                       "reading " << i << ": orientation given for some readings but not all");
    VRREG_THROW_UNLESS(
        r.q_robot_marker.has_value() == first.q_robot_marker.has_value(),
        "reading " << i << ": commanded orientation given for some readings but not all");
    VRREG_THROW_UNLESS(!r.q_robot_marker || r.q_sensor_marker,
                       "reading " << i << ": a commanded orientation without a measured one");
    VRREG_THROW_UNLESS(r.q_rad.size() == n_joints, "reading " << i << " has " << r.q_rad.size()
                                                              << " joint angles, reading 0 has "
                                                              << n_joints);
    VRREG_THROW_UNLESS(r.from_q_rad.size() == first.from_q_rad.size() &&
                           (r.from_q_rad.empty() || r.from_q_rad.size() == n_joints),
                       "reading " << i << ": from_q given for some readings but not all, or not "
                                     "one per joint");
  }
  std::string out;
  append_comments(out, comments);
  out += "point,role";
  if (first.has_robot) out += ",robot_x_mm,robot_y_mm,robot_z_mm";
  out += ",sensor_x_mm,sensor_y_mm,sensor_z_mm";
  if (first.config) out += ",config";
  for (std::size_t k = 0; k < n_joints; ++k) out += ",q" + std::to_string(k + 1) + "_rad";
  for (std::size_t k = 0; k < first.from_q_rad.size(); ++k) {
    out += ",from_q" + std::to_string(k + 1) + "_rad";
  }
  if (first.repeat) out += ",repeat";
  if (first.visit) out += ",visit";
  if (first.q_sensor_marker) out += ",sensor_qx,sensor_qy,sensor_qz,sensor_qw";
  if (first.q_robot_marker) out += ",robot_qx,robot_qy,robot_qz,robot_qw";
  out += '\n';
  for (std::size_t i = 0; i < readings.size(); ++i) {
    const Reading& r = readings[i];
    out += r.point;
    out += ',';
    out += to_string(r.role);
    if (r.has_robot) append_mm(out, r.robot_m, i);
    append_mm(out, r.sensor_m, i);
    if (r.config) out += "," + std::to_string(*r.config);
    for (const double q : r.q_rad) {
      VRREG_THROW_UNLESS(std::isfinite(q), "reading " << i << ": non-finite joint angle");
      out += ',';
      out += detail::format_double(q);
    }
    for (const double q : r.from_q_rad) {
      VRREG_THROW_UNLESS(std::isfinite(q), "reading " << i << ": non-finite from_q angle");
      out += ',';
      out += detail::format_double(q);
    }
    if (r.repeat) out += "," + std::to_string(*r.repeat);
    if (r.visit) out += "," + std::to_string(*r.visit);
    if (r.q_sensor_marker) append_quaternion(out, *r.q_sensor_marker, i);
    if (r.q_robot_marker) append_quaternion(out, *r.q_robot_marker, i);
    out += '\n';
  }
  return out;
}

void write_measurement_csv(const std::string& path, const std::vector<Reading>& readings,
                           const std::vector<std::string>& comments) {
  write_file_atomically(path, format_measurement_csv(readings, comments));
}

}  // namespace vrreg::io
