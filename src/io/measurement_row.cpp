// SPDX-License-Identifier: Apache-2.0
#include "measurement_row.hpp"

#include <cmath>

#include "csv_fields.hpp"
#include "text_checks.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::io::detail {
namespace {

class RowParser {
 public:
  RowParser(const std::vector<std::string_view>& fields, const MeasurementColumns& columns,
            const std::string& source, std::size_t line)
      : fields_(fields), columns_(columns), source_(source), line_(line) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw FileError(source_, line_, message);
  }

  std::string_view field(int index) const { return fields_[static_cast<std::size_t>(index)]; }

  std::string column_name(int index) const {
    return printable(columns_.names[static_cast<std::size_t>(index)]);
  }

  double number(int index) const {
    const std::string_view text = field(index);
    const std::optional<double> value = parse_finite_double(text);
    if (!value) {
      fail("column '" + column_name(index) + "': " +
           (text.empty() ? std::string("empty value")
                         : "'" + printable(text) + "' is not a finite number"));
    }
    return *value;
  }

  int integer(int index) const {
    const std::string_view text = field(index);
    const std::optional<int> value = parse_int(text);
    if (!value) {
      fail("column '" + column_name(index) + "': " +
           (text.empty() ? std::string("empty value")
                         : "'" + printable(text) + "' is not an integer"));
    }
    return *value;
  }

  Eigen::Vector3d position_m(const std::array<int, 3>& indices, std::string_view point) const {
    Eigen::Vector3d p;
    for (int axis = 0; axis < 3; ++axis) {
      const int index = indices[static_cast<std::size_t>(axis)];
      const double value = number(index);
      // Dividing by 1000 rounds correctly; multiplying by the inexact 1e-3 may not.
      p(axis) = columns_.length_in_mm ? value / units::kMillimetresPerMetre : value;
      if (const std::string why = coordinate_out_of_range(p(axis), column_name(index),
                                                          printable(field(index)));
          !why.empty()) {
        fail("point '" + printable(point) + "', " + why);
      }
    }
    return p;
  }

  void parse(MeasurementRow& row) const {
    for (std::size_t i = 0; i < fields_.size(); ++i) {
      if (!fields_[i].empty() && fields_[i].front() == '"') {
        fail("column '" + column_name(static_cast<int>(i)) +
             "': quoted fields are not supported (labels may not contain commas or quotes)");
      }
    }
    row.point = field(columns_.point);
    if (row.point.empty()) fail("empty point label");
    const std::string role = to_lower(field(columns_.role));
    if (role == "fiducial") {
      row.role = Role::kFiducial;
    } else if (role == "target") {
      row.role = Role::kTarget;
    } else if (role == "monitor") {
      row.role = Role::kMonitor;
    } else {
      fail("unknown role '" + printable(field(columns_.role)) +
           "' (expected fiducial, target or monitor)");
    }
    row.robot_m =
        columns_.has_robot() ? position_m(columns_.robot, row.point) : Eigen::Vector3d::Zero();
    row.sensor_m = position_m(columns_.sensor, row.point);
    row.config.reset();
    if (columns_.config != MeasurementColumns::kAbsent) row.config = integer(columns_.config);
    row.repeat.reset();
    if (columns_.repeat != MeasurementColumns::kAbsent) {
      row.repeat = integer(columns_.repeat);
      if (*row.repeat < 0) fail("column '" + column_name(columns_.repeat) + "': negative repeat");
    }
    row.visit.reset();
    if (columns_.visit != MeasurementColumns::kAbsent) {
      row.visit = integer(columns_.visit);
      if (*row.visit < 0) fail("column '" + column_name(columns_.visit) + "': negative visit");
    }
    row.q_rad.resize(columns_.joints.size());
    for (std::size_t k = 0; k < columns_.joints.size(); ++k) {
      const double value = number(columns_.joints[k]);
      row.q_rad[k] = columns_.joints_in_degrees ? units::deg_to_rad(value) : value;
    }
    row.from_q_rad.resize(columns_.from_joints.size());
    for (std::size_t k = 0; k < columns_.from_joints.size(); ++k) {
      const double value = number(columns_.from_joints[k]);
      row.from_q_rad[k] = columns_.joints_in_degrees ? units::deg_to_rad(value) : value;
    }
    row.q_sensor_marker.reset();
    if (columns_.has_orientation())
      row.q_sensor_marker = quaternion(columns_.orientation, "sensor");
    row.q_robot_marker.reset();
    if (columns_.has_robot_orientation()) {
      row.q_robot_marker = quaternion(columns_.robot_orientation, "robot");
    }
  }

 private:
  // The unit quaternion in columns x, y, z, w of `frame` ("sensor" or "robot").
  Eigen::Quaterniond quaternion(const std::array<int, 4>& c, const std::string& frame) const {
    const Eigen::Quaterniond q(number(c[3]), number(c[0]), number(c[1]), number(c[2]));
    if (!(std::abs(q.norm() - 1.0) <= kQuaternionNormTolerance)) {
      fail(frame + "_qx.." + frame + "_qw: the quaternion's norm is " + format_double(q.norm()) +
           ", not 1 (within " + format_double(kQuaternionNormTolerance) +
           "); give the orientation as a unit quaternion");
    }
    return q.normalized();
  }

  const std::vector<std::string_view>& fields_;
  const MeasurementColumns& columns_;
  const std::string& source_;
  std::size_t line_;
};

}  // namespace

void parse_measurement_row(const std::vector<std::string_view>& fields,
                           const MeasurementColumns& columns, const std::string& source,
                           std::size_t line, MeasurementRow& row) {
  if (fields.size() != columns.names.size()) {
    throw FileError(source, line,
                    std::string(fields.size() < columns.names.size() ? "short" : "long") +
                        " row: " + std::to_string(fields.size()) + " fields, the header has " +
                        std::to_string(columns.names.size()));
  }
  RowParser(fields, columns, source, line).parse(row);
}

}  // namespace vrreg::io::detail
