// SPDX-License-Identifier: Apache-2.0
#include "measurement_header.hpp"

#include <map>
#include <optional>
#include <string_view>

#include "csv_fields.hpp"
#include "text_checks.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::io::detail {
namespace {

constexpr int kMaxJoints = 64;
constexpr const char* kAllowed =
    "allowed: point, role, robot_x_mm, robot_y_mm, robot_z_mm, sensor_x_mm, sensor_y_mm, "
    "sensor_z_mm (or all six with _m), config, q1_rad..qN_rad (or _deg), repeat, visit, sensor_qx, "
    "sensor_qy, sensor_qz, sensor_qw, robot_qx, robot_qy, robot_qz, robot_qw, from_q1_rad.."
    "from_qN_rad (or _deg)";

// "<frame>_qx".."<frame>_qw" (frame "sensor" or "robot"): an orientation quaternion
// (unitless); index x,y,z,w = 0..3.
std::optional<int> orientation_column(const std::string& lower, const std::string& frame) {
  if (lower.size() != frame.size() + 3 || !lower.starts_with(frame + "_q")) return std::nullopt;
  static constexpr std::string_view kComponents = "xyzw";
  const std::size_t k = kComponents.find(lower.back());
  if (k == std::string_view::npos) return std::nullopt;
  return static_cast<int>(k);
}

// Splits "<stem>_<suffix>" at the last underscore; the suffix is empty when there is none.
std::pair<std::string, std::string> split_suffix(const std::string& name) {
  const std::size_t underscore = name.rfind('_');
  if (underscore == std::string::npos) return {name, ""};
  return {name.substr(0, underscore), name.substr(underscore + 1)};
}

// Recognises "robot_x", "sensor_z": returns 0 (robot) / 1 (sensor) and the axis; nullopt otherwise.
std::optional<std::pair<int, int>> coordinate_stem(const std::string& stem) {
  for (int frame = 0; frame < 2; ++frame) {
    const std::string prefix = frame == 0 ? "robot_" : "sensor_";
    if (stem.size() == prefix.size() + 1 && stem.starts_with(prefix)) {
      const char axis = stem.back();
      if (axis >= 'x' && axis <= 'z') return std::pair{frame, axis - 'x'};
    }
  }
  return std::nullopt;
}

// Recognises "q<k>" with k a positive decimal: returns k (0 for "q0"); nullopt otherwise.
std::optional<int> joint_stem(const std::string& stem) {
  if (stem.size() < 2 || stem.front() != 'q') return std::nullopt;
  for (std::size_t i = 1; i < stem.size(); ++i) {
    if (stem[i] < '0' || stem[i] > '9') return std::nullopt;
  }
  if (stem.size() > 4) return kMaxJoints + 1;
  return parse_int(std::string_view(stem).substr(1));
}

class HeaderParser {
 public:
  HeaderParser(const std::string& source, std::size_t line) : source_(source), line_(line) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw FileError(source_, line_, "header: " + message);
  }

  // Records that `key` (a canonical quantity name) is in column `index`; duplicates are errors.
  void claim(const std::string& key, int index, const MeasurementColumns& cols) {
    const auto [it, inserted] = seen_.emplace(key, index);
    if (!inserted) {
      fail("duplicate column '" + printable(cols.names[static_cast<std::size_t>(index)]) +
           "' (columns " + std::to_string(it->second + 1) + " and " + std::to_string(index + 1) +
           ")");
    }
  }

  // All length (or all angle) columns must share one unit suffix.
  void check_unit(std::optional<std::string>& first_column, std::string& first_unit,
                  const std::string& column, const std::string& unit, const char* what) {
    if (!first_column) {
      first_column = column;
      first_unit = unit;
    } else if (unit != first_unit) {
      fail("mixed " + std::string(what) + " units: column '" + column + "' uses _" + unit +
           " but column '" + *first_column + "' uses _" + first_unit +
           " (all must use the same unit)");
    }
  }

  MeasurementColumns parse(const std::vector<std::string_view>& fields, bool require_robot) {
    MeasurementColumns cols;
    for (const std::string_view field : fields) cols.names.emplace_back(field);
    std::optional<std::string> length_column;
    std::optional<std::string> angle_column;
    std::string length_unit = "mm";
    std::string angle_unit = "rad";
    int max_joint = 0;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const int index = static_cast<int>(i);
      const std::string& name = cols.names[i];
      const std::string shown = printable(name);
      if (name.empty()) fail("empty column name (column " + std::to_string(i + 1) + ")");
      if (name.front() == '"') {
        fail("quoted column name " + shown + " (quoting is not supported)");
      }
      const std::string lower = to_lower(name);
      if (lower == "point" || lower == "role" || lower == "config" || lower == "repeat" ||
          lower == "visit") {
        claim(lower, index, cols);
        (lower == "point"    ? cols.point
         : lower == "role"   ? cols.role
         : lower == "config" ? cols.config
         : lower == "visit"  ? cols.visit
                             : cols.repeat) = index;
        continue;
      }
      if (const auto component = orientation_column(lower, "sensor")) {
        claim(lower, index, cols);
        cols.orientation[static_cast<std::size_t>(*component)] = index;
        continue;
      }
      if (const auto component = orientation_column(lower, "robot")) {
        claim(lower, index, cols);
        cols.robot_orientation[static_cast<std::size_t>(*component)] = index;
        continue;
      }
      if (lower.starts_with("from_")) {  // the joints the robot came from (lost motion)
        const auto [from_stem, from_unit] = split_suffix(lower.substr(5));
        const auto joint = joint_stem(from_stem);
        if (!joint) fail("unknown column '" + shown + "' (" + kAllowed + ")");
        if (from_unit != "rad" && from_unit != "deg") {
          fail("column '" + shown + "' needs the unit suffix _rad or _deg");
        }
        if (*joint < 1 || *joint > kMaxJoints) {
          fail("column '" + shown + "': joint columns are from_q1..from_q" +
               std::to_string(kMaxJoints));
        }
        claim("from_" + from_stem, index, cols);
        check_unit(angle_column, angle_unit, name, from_unit, "angle");
        if (static_cast<std::size_t>(*joint) > cols.from_joints.size()) {
          cols.from_joints.resize(static_cast<std::size_t>(*joint), MeasurementColumns::kAbsent);
        }
        cols.from_joints[static_cast<std::size_t>(*joint - 1)] = index;
        continue;
      }
      const auto [stem, unit] = split_suffix(lower);
      if (const auto coordinate = coordinate_stem(stem)) {
        if (unit.empty()) fail("column '" + shown + "' has no unit suffix (_mm or _m)");
        if (unit != "mm" && unit != "m") {
          fail("column '" + shown + "': unknown unit suffix '_" + printable(unit) +
               "' (expected _mm or _m)");
        }
        claim(stem, index, cols);
        check_unit(length_column, length_unit, name, unit, "length");
        (coordinate->first == 0 ? cols.robot : cols.sensor)[coordinate->second] = index;
        continue;
      }
      if (coordinate_stem(lower)) fail("column '" + shown + "' has no unit suffix (_mm or _m)");
      if (joint_stem(lower)) fail("column '" + shown + "' has no unit suffix (_rad or _deg)");
      if (const auto joint = joint_stem(stem)) {
        if (unit.empty()) fail("column '" + shown + "' has no unit suffix (_rad or _deg)");
        if (unit != "rad" && unit != "deg") {
          fail("column '" + shown + "': unknown unit suffix '_" + printable(unit) +
               "' (expected _rad or _deg)");
        }
        if (*joint < 1 || *joint > kMaxJoints) {
          fail("column '" + shown + "': joint columns are q1..q" + std::to_string(kMaxJoints));
        }
        claim(stem, index, cols);
        check_unit(angle_column, angle_unit, name, unit, "angle");
        if (*joint > max_joint) {
          max_joint = *joint;
          cols.joints.resize(static_cast<std::size_t>(max_joint), MeasurementColumns::kAbsent);
        }
        cols.joints[static_cast<std::size_t>(*joint - 1)] = index;
        continue;
      }
      fail("unknown column '" + shown + "' (" + kAllowed + ")");
    }
    cols.length_in_mm = length_unit == "mm";
    cols.joints_in_degrees = angle_unit == "deg";
    check_required(cols, require_robot, length_unit, angle_unit);
    return cols;
  }

 private:
  void check_required(const MeasurementColumns& cols, bool require_robot,
                      const std::string& length_unit, const std::string& angle_unit) const {
    const auto missing = [&](const std::string& column) {
      fail("missing column '" + column + "' (" + kAllowed + ")");
    };
    if (cols.point == MeasurementColumns::kAbsent) missing("point");
    if (cols.role == MeasurementColumns::kAbsent) missing("role");
    const bool any_robot = cols.robot[0] != MeasurementColumns::kAbsent ||
                           cols.robot[1] != MeasurementColumns::kAbsent ||
                           cols.robot[2] != MeasurementColumns::kAbsent;
    for (int axis = 0; axis < 3; ++axis) {
      const std::string suffix = std::string(1, static_cast<char>('x' + axis)) + "_" + length_unit;
      if ((require_robot || any_robot) && cols.robot[static_cast<std::size_t>(axis)] < 0) {
        missing("robot_" + suffix);
      }
      if (cols.sensor[static_cast<std::size_t>(axis)] < 0) missing("sensor_" + suffix);
    }
    check_quaternion_columns(cols.orientation, "sensor", "the marker orientation");
    check_quaternion_columns(cols.robot_orientation, "robot", "the commanded orientation");
    if (cols.has_robot_orientation() && !cols.has_orientation()) {
      fail(
          "robot_qx..robot_qw without sensor_qx..sensor_qw (a commanded orientation needs the "
          "measured one)");
    }
    for (std::size_t k = 0; k < cols.joints.size(); ++k) {
      if (cols.joints[k] == MeasurementColumns::kAbsent) {
        fail("joint columns must be q1..q" + std::to_string(cols.joints.size()) +
             " without gaps: " + "missing column 'q" + std::to_string(k + 1) + "_" + angle_unit +
             "'");
      }
    }
    if (!cols.from_joints.empty() && cols.from_joints.size() != cols.joints.size()) {
      fail("from_q columns need one per joint column: " + std::to_string(cols.from_joints.size()) +
           " from_q, " + std::to_string(cols.joints.size()) + " q");
    }
    for (std::size_t k = 0; k < cols.from_joints.size(); ++k) {
      if (cols.from_joints[k] == MeasurementColumns::kAbsent) {
        fail("missing column 'from_q" + std::to_string(k + 1) + "_" + angle_unit + "'");
      }
    }
  }

  // All four components of a quaternion, or none.
  void check_quaternion_columns(const std::array<int, 4>& columns, const std::string& frame,
                                const std::string& what) const {
    int n = 0;
    for (const int index : columns) n += index >= 0 ? 1 : 0;
    if (n == 0 || n == 4) return;
    for (int k = 0; k < 4; ++k) {
      if (columns[static_cast<std::size_t>(k)] < 0) {
        fail("missing column '" + frame + "_q" + "xyzw"[k] + "' (" + what + " needs all of " +
             frame + "_qx, " + frame + "_qy, " + frame + "_qz, " + frame + "_qw, or none)");
      }
    }
  }

  const std::string& source_;
  std::size_t line_;
  std::map<std::string, int> seen_;
};

}  // namespace

MeasurementColumns parse_measurement_header(const std::vector<std::string_view>& fields,
                                            const std::string& source, std::size_t line,
                                            bool require_robot) {
  return HeaderParser(source, line).parse(fields, require_robot);
}

}  // namespace vrreg::io::detail
