// SPDX-License-Identifier: Apache-2.0
#pragma once
// The header line of a measurement CSV: which field holds which quantity, in which unit.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace vrreg::io::detail {

/// Column positions (indices into a row's fields) and unit factors of a measurement CSV.
struct MeasurementColumns {
  static constexpr int kAbsent = -1;
  std::vector<std::string> names;  ///< header names as written (trimmed)
  int point = kAbsent;
  int role = kAbsent;
  std::array<int, 3> robot{kAbsent, kAbsent, kAbsent};
  std::array<int, 3> sensor{kAbsent, kAbsent, kAbsent};
  int config = kAbsent;
  int repeat = kAbsent;
  int visit = kAbsent;
  std::vector<int> joints;   ///< q1..qN
  std::vector<int> from_joints;  ///< from_q1..from_qN (the joints the robot came from), or empty
  std::array<int, 4> orientation{kAbsent, kAbsent, kAbsent, kAbsent};  ///< sensor_qx..qw
  std::array<int, 4> robot_orientation{kAbsent, kAbsent, kAbsent, kAbsent};  ///< robot_qx..qw
  bool length_in_mm = true;  ///< _mm columns (else _m)
  bool joints_in_degrees = false;
  [[nodiscard]] bool has_robot() const { return robot[0] != kAbsent; }
  [[nodiscard]] bool has_orientation() const { return orientation[0] != kAbsent; }
  [[nodiscard]] bool has_robot_orientation() const { return robot_orientation[0] != kAbsent; }
};

/// Parses header `fields` (line `line` of `source`); throws FileError on any problem.
MeasurementColumns parse_measurement_header(const std::vector<std::string_view>& fields,
                                            const std::string& source, std::size_t line,
                                            bool require_robot);

}  // namespace vrreg::io::detail
