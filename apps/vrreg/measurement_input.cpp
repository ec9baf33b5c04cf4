// SPDX-License-Identifier: Apache-2.0
#include "measurement_input.hpp"

#include <fmt/format.h>

#include <iostream>
#include <limits>

namespace vrreg::cli {
namespace {

// The largest per-axis span of the robot or sensor positions [m], and which frame has it.
struct Span {
  double metres = 0.0;
  const char* frame = "robot";
};

Span largest_span(const MeasurementSet& set) {
  Eigen::Vector3d robot_lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d robot_hi = -robot_lo, sensor_lo = robot_lo, sensor_hi = -robot_lo;
  for (const Location& l : set.locations) {
    if (l.has_robot) {
      robot_lo = robot_lo.cwiseMin(l.robot_m);
      robot_hi = robot_hi.cwiseMax(l.robot_m);
    }
    sensor_lo = sensor_lo.cwiseMin(l.sensor_m);
    sensor_hi = sensor_hi.cwiseMax(l.sensor_m);
  }
  Span span;
  if (robot_hi.x() >= robot_lo.x()) span.metres = (robot_hi - robot_lo).maxCoeff();
  if (sensor_hi.x() >= sensor_lo.x() && (sensor_hi - sensor_lo).maxCoeff() > span.metres) {
    span = {(sensor_hi - sensor_lo).maxCoeff(), "sensor"};
  }
  return span;
}

}  // namespace

std::string implausible_extent_warning(const MeasurementSet& set) {
  const Span span = largest_span(set);
  if (!(span.metres > kMaxPlausibleSpanM)) return "";
  return fmt::format(
      "{}: the {} positions span {:.1f} m, more than a robot cell; if the file's columns end in "
      "_m, were millimetres written in them (use _mm)?",
      set.source, span.frame, span.metres);
}

MeasurementSet read_measurements(const std::string& path, const io::CsvReadOptions& options) {
  MeasurementSet set = io::read_measurement_csv(path, options);
  if (const std::string warning = implausible_extent_warning(set); !warning.empty()) {
    std::cerr << "vrreg: warning: " << warning << "\n";
  }
  return set;
}

}  // namespace vrreg::cli
