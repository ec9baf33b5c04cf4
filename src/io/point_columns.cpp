// SPDX-License-Identifier: Apache-2.0
#include "point_columns.hpp"

#include <map>
#include <optional>

#include "csv_fields.hpp"
#include "text_checks.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::io::detail {
namespace {

constexpr int kMaxJointColumns = 64;

// "robot_x" / "sensor_z" -> (frame 0 robot / 1 sensor, axis); nullopt otherwise.
std::optional<std::pair<int, int>> coordinate(const std::string& stem) {
  for (int frame = 0; frame < 2; ++frame) {
    const std::string prefix = frame == 0 ? "robot_" : "sensor_";
    if (stem.size() == prefix.size() + 1 && stem.starts_with(prefix) && stem.back() >= 'x' &&
        stem.back() <= 'z') {
      return std::pair{frame, stem.back() - 'x'};
    }
  }
  return std::nullopt;
}

// "q<k>" -> k; nullopt otherwise.
std::optional<int> joint(const std::string& stem) {
  if (stem.size() < 2 || stem.size() > 4 || stem.front() != 'q') return std::nullopt;
  return parse_int(std::string_view(stem).substr(1));
}

}  // namespace

PointColumns parse_point_columns(const std::vector<std::string_view>& fields,
                                 const std::string& source, std::size_t line,
                                 const PointColumnRules& rules) {
  const auto fail = [&](const std::string& message) {
    throw FileError(source, line, "header: " + message);
  };
  PointColumns cols;
  std::map<std::string, int> seen;
  std::string length_unit;
  std::string angle_unit;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const int index = static_cast<int>(i);
    cols.names.emplace_back(fields[i]);
    const std::string shown = printable(fields[i]);
    if (fields[i].empty()) fail("empty column name (column " + std::to_string(i + 1) + ")");
    const std::string lower = to_lower(fields[i]);
    const std::size_t underscore = lower.rfind('_');
    const std::string stem = underscore == std::string::npos ? lower : lower.substr(0, underscore);
    const std::string unit = underscore == std::string::npos ? "" : lower.substr(underscore + 1);
    const auto claim = [&](const std::string& key) {
      const auto [it, inserted] = seen.emplace(key, index);
      if (!inserted) {
        fail("duplicate column '" + shown + "' (columns " + std::to_string(it->second + 1) +
             " and " + std::to_string(i + 1) + ")");
      }
    };
    const auto same_unit = [&](std::string& first, const char* what) {
      if (first.empty()) first = unit;
      if (unit != first) {
        fail("mixed " + std::string(what) + " units: column '" + shown + "' uses _" + unit +
             " but another uses _" + first);
      }
    };
    int* simple = lower == "point"    ? &cols.point
                  : lower == "role"   ? &cols.role
                  : lower == "part"   ? (rules.part ? &cols.part : nullptr)
                  : lower == "config" ? &cols.config
                  : lower == "repeat" ? (rules.measurement_extras ? &cols.repeat : nullptr)
                                      : nullptr;
    if (simple != nullptr) {
      claim(lower);
      *simple = index;
    } else if (const auto c = coordinate(stem); c && (c->first == 0 || rules.measurement_extras)) {
      if (unit != "mm" && unit != "m") fail("column '" + shown + "': unit must be _mm or _m");
      claim(stem);
      same_unit(length_unit, "length");
      (c->first == 0 ? cols.robot : cols.sensor)[static_cast<std::size_t>(c->second)] = index;
    } else if (const auto k = joint(stem)) {
      if (unit != "rad" && unit != "deg") fail("column '" + shown + "': unit must be _rad or _deg");
      if (*k < 1 || *k > kMaxJointColumns) fail("column '" + shown + "': joints are q1..q64");
      claim(stem);
      same_unit(angle_unit, "angle");
      if (static_cast<std::size_t>(*k) > cols.joints.size()) {
        cols.joints.resize(static_cast<std::size_t>(*k), PointColumns::kAbsent);
      }
      cols.joints[static_cast<std::size_t>(*k - 1)] = index;
    } else if (coordinate(lower)) {
      fail("column '" + shown + "' has no unit suffix (_mm or _m)");
    } else if (joint(lower)) {
      fail("column '" + shown + "' has no unit suffix (_rad or _deg)");
    } else {
      fail("unknown column '" + shown + "' in a " + rules.file_kind + " (" + rules.allowed + ")");
    }
  }
  cols.length_in_mm = length_unit != "m";
  cols.joints_in_degrees = angle_unit == "deg";
  if (cols.point == PointColumns::kAbsent)
    fail("missing column 'point' (" + std::string(rules.allowed) + ")");
  for (int axis = 0; axis < 3; ++axis) {
    if (cols.robot[static_cast<std::size_t>(axis)] == PointColumns::kAbsent) {
      fail("missing column 'robot_" + std::string(1, static_cast<char>('x' + axis)) + "_" +
           (length_unit.empty() ? "mm" : length_unit) + "'");
    }
  }
  for (std::size_t k = 0; k < cols.joints.size(); ++k) {
    if (cols.joints[k] == PointColumns::kAbsent) {
      fail("joint columns must be q1..q" + std::to_string(cols.joints.size()) +
           " without gaps: missing 'q" + std::to_string(k + 1) + "_" + angle_unit + "'");
    }
  }
  return cols;
}

std::array<double, 3> parse_robot_m(const std::vector<std::string_view>& fields,
                                    const PointColumns& columns, const std::string& source,
                                    std::size_t line) {
  std::array<double, 3> out{};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const auto column = static_cast<std::size_t>(columns.robot[axis]);
    const std::optional<double> v = parse_finite_double(fields[column]);
    if (!v) {
      throw FileError(source, line,
                      "column '" + columns.names[column] + "': not a finite number: '" +
                          printable(fields[column]) + "'");
    }
    out[axis] = columns.length_in_mm ? units::mm_to_m(*v) : *v;
    if (const std::string why =
            coordinate_out_of_range(out[axis], columns.names[column], printable(fields[column]));
        !why.empty()) {
      throw FileError(source, line, why);
    }
  }
  return out;
}

void check_field_count(const std::vector<std::string_view>& fields, const PointColumns& columns,
                       const std::string& source, std::size_t line) {
  if (fields.size() != columns.names.size()) {
    throw FileError(source, line,
                    "expected " + std::to_string(columns.names.size()) +
                        " fields (as the header), got " + std::to_string(fields.size()));
  }
}

std::string parse_point_label(std::string_view field, const std::string& source, std::size_t line) {
  if (field.empty()) throw FileError(source, line, "empty point label");
  if (field.front() == '"') {
    throw FileError(source, line,
                    "quoted field " + printable(field) + " (quoting is not supported)");
  }
  return std::string(field);
}

std::string plan_label(std::string_view text, const char* what, const std::string& source,
                       std::size_t line) {
  if (text.find('"') != std::string_view::npos || (!text.empty() && text.front() == '#')) {
    throw FileError(source, line,
                    std::string(what) + " label '" + printable(text) +
                        "' has a quote or a leading '#' (plan labels cannot)");
  }
  return std::string(text);
}

bool all_fields_empty(const std::vector<std::string_view>& fields) {
  for (const std::string_view f : fields) {
    if (!f.empty()) return false;
  }
  return true;
}

}  // namespace vrreg::io::detail
