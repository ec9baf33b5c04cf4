// SPDX-License-Identifier: Apache-2.0
#pragma once
// Header of the point files other than the measurement CSV (parts file, plan file): the columns
// point, role, part, robot_{x,y,z}_mm|_m, sensor_{x,y,z}_mm|_m, config, repeat, q1..qN_rad|_deg,
// recognised case-insensitively; each reader says which of them it takes.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace vrreg::io::detail {

/// Column positions of a point file's header.
struct PointColumns {
  static constexpr int kAbsent = -1;
  std::vector<std::string> names;  ///< header names as written (trimmed)
  int point = kAbsent;
  int role = kAbsent;
  int part = kAbsent;
  int config = kAbsent;
  int repeat = kAbsent;
  std::array<int, 3> robot{kAbsent, kAbsent, kAbsent};
  std::array<int, 3> sensor{kAbsent, kAbsent, kAbsent};
  std::vector<int> joints;   ///< q1..qN, contiguous
  bool length_in_mm = true;  ///< robot (and sensor) columns in _mm (else _m)
  bool joints_in_degrees = false;
};

/// What a reader takes beyond point and robot_{x,y,z} (which are required).
struct PointColumnRules {
  const char* file_kind = "point file";  ///< for messages, e.g. "parts file"
  const char* allowed = "";              ///< list of allowed columns, for messages
  bool part = false;                     ///< a `part` column may appear
  bool measurement_extras = false;       ///< sensor_*, repeat may appear (the reader ignores them)
};

/// Parses header `fields` (line `line` of `source`); throws FileError on an unknown, duplicate,
/// unit-less or mixed-unit column, a gap in q1..qN, or a missing required column.
PointColumns parse_point_columns(const std::vector<std::string_view>& fields,
                                 const std::string& source, std::size_t line,
                                 const PointColumnRules& rules);

/// Reads robot_{x,y,z} of a row into metres; throws FileError naming the column otherwise.
std::array<double, 3> parse_robot_m(const std::vector<std::string_view>& fields,
                                    const PointColumns& columns, const std::string& source,
                                    std::size_t line);

/// Checks a row has as many fields as the header; throws FileError otherwise.
void check_field_count(const std::vector<std::string_view>& fields, const PointColumns& columns,
                       const std::string& source, std::size_t line);

/// A point label from `field`: not empty, not quoted; throws FileError otherwise.
std::string parse_point_label(std::string_view field, const std::string& source, std::size_t line);

/// `text` as a plan file's `what` label ("point", "part"): one the plan writer can write back
/// (plan_csv.hpp), so no quote and no leading '#' (a comma, newline or surrounding space cannot
/// survive the split and trim); throws FileError otherwise.
std::string plan_label(std::string_view text, const char* what, const std::string& source,
                       std::size_t line);

/// True when every field is empty (a spreadsheet's blank row).
bool all_fields_empty(const std::vector<std::string_view>& fields);

}  // namespace vrreg::io::detail
