// SPDX-License-Identifier: Apache-2.0
#pragma once
// Folds the rows of a measurement CSV into locations as they stream past: repeat readings of one
// (point, config) are averaged with Welford's update, so memory grows with the locations only.
#include <cstddef>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "measurement_row.hpp"
#include "vrreg/core/measurement.hpp"

namespace vrreg::io::detail {

/// Accumulates rows into locations, checking that repeats of a point agree.
class LocationAccumulator {
 public:
  /// `has_robot`: the file has robot columns; tolerances as in CsvReadOptions.
  LocationAccumulator(std::string source, bool has_robot, double robot_tolerance_m,
                      double joint_tolerance_rad);

  /// Adds the row read on line `line`; throws FileError naming both lines on a conflict.
  void add(const MeasurementRow& row, std::size_t line);
  /// Number of rows added so far.
  [[nodiscard]] std::size_t rows() const { return rows_; }
  /// The locations in the order of their first reading.
  /// The locations in the order of their first reading; orientations averaged (see .cpp).
  std::vector<Location> take();

 private:
  struct PointEntry {
    Role role;
    Eigen::Vector3d robot_m;
    std::size_t first_line;
    /// (config, visit) -> index into the locations
    std::vector<std::pair<std::pair<std::optional<int>, std::optional<int>>, std::size_t>>
        locations;
  };

  void check_point(const PointEntry& entry, const MeasurementRow& row, std::size_t line) const;
  void check_joints(const Location& location, const MeasurementRow& row, std::size_t line) const;

  std::string source_;
  bool has_robot_;
  double robot_tolerance_m_;
  double joint_tolerance_rad_;
  std::unordered_map<std::string, PointEntry> points_;
  std::vector<Location> locations_;
  std::vector<Eigen::Matrix4d> orientation_sums_;  ///< per location: sum of q q' over readings
  std::string key_;
  std::size_t rows_ = 0;
};

}  // namespace vrreg::io::detail
