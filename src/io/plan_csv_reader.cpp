// SPDX-License-Identifier: Apache-2.0
#include <fstream>
#include <map>
#include <optional>

#include "csv_fields.hpp"
#include "line_reader.hpp"
#include "point_columns.hpp"
#include "text_checks.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/input_file.hpp"
#include "vrreg/io/plan_csv.hpp"

namespace vrreg::io {
namespace {

constexpr std::size_t kPlanMaxLineBytes = 1024 * 1024;

const detail::PointColumnRules kPlanRules{
    "plan file",
    "a plan file has point, role, part, robot_x_mm, robot_y_mm, robot_z_mm (or _m), config, "
    "q1_rad..qN_rad (or _deg)",
    true, false};

std::string_view field(const std::vector<std::string_view>& fields, int column) {
  return fields[static_cast<std::size_t>(column)];
}

// `via` tells whether the row is a via point (role "via") rather than a location.
PlanRow parse_row(const std::vector<std::string_view>& fields, const detail::PointColumns& cols,
                  const std::string& source, std::size_t line, bool& via) {
  detail::check_field_count(fields, cols, source, line);
  PlanRow row;
  row.line = line;
  row.point = detail::plan_label(detail::parse_point_label(field(fields, cols.point), source, line),
                                 "point", source, line);
  const std::string role = detail::to_lower(field(fields, cols.role));
  via = role == "via";
  if (role != "fiducial" && role != "target" && role != "monitor" && !via) {
    throw FileError(source, line,
                    "role must be 'fiducial', 'target', 'monitor' or 'via', got '" +
                        detail::printable(field(fields, cols.role)) + "'");
  }
  row.role = role == "target"    ? Role::kTarget
             : role == "monitor" ? Role::kMonitor
                                 : Role::kFiducial;
  if (cols.part != detail::PointColumns::kAbsent) {
    row.part = detail::plan_label(field(fields, cols.part), "part", source, line);
  }
  const std::array<double, 3> xyz = detail::parse_robot_m(fields, cols, source, line);
  row.robot_m = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
  if (cols.config != detail::PointColumns::kAbsent) {
    row.config = detail::parse_int(field(fields, cols.config));
    if (!row.config) {
      throw FileError(
          source, line,
          "config must be an integer, got '" + detail::printable(field(fields, cols.config)) + "'");
    }
  }
  for (std::size_t k = 0; k < cols.joints.size(); ++k) {
    const std::optional<double> q = detail::parse_finite_double(field(fields, cols.joints[k]));
    if (!q) {
      throw FileError(source, line,
                      "column '" + cols.names[static_cast<std::size_t>(cols.joints[k])] +
                          "': not a finite number: '" +
                          detail::printable(field(fields, cols.joints[k])) + "'");
    }
    row.q_rad.push_back(cols.joints_in_degrees ? units::deg_to_rad(*q) : *q);
  }
  return row;
}

}  // namespace

PlanFile parse_plan_csv(std::istream& in, const std::string& source_name) {
  detail::LineReader reader(in, source_name, kPlanMaxLineBytes);
  std::string line;
  std::vector<std::string_view> fields;
  std::optional<detail::PointColumns> columns;
  std::size_t header_line = 0;
  PlanFile plan;
  std::map<std::pair<std::string, int>, std::size_t> seen;
  std::optional<PlanRow> pending_via;  // a via row waiting for its location's row
  while (reader.next(line)) {
    const std::string_view content = detail::trim(line);
    if (!content.empty() && content.front() == '#') {
      std::string_view text = content.substr(1);
      if (text.starts_with(' ')) text.remove_prefix(1);
      plan.comments.emplace_back(text);
      continue;
    }
    if (content.empty()) continue;
    detail::split_fields(line, fields);
    if (detail::all_fields_empty(fields)) continue;
    const std::size_t at = reader.line_number();
    if (!columns) {
      header_line = at;
      columns = detail::parse_point_columns(fields, source_name, at, kPlanRules);
      if (columns->role == detail::PointColumns::kAbsent) {
        throw FileError(source_name, at,
                        "header: missing column 'role' (" + std::string(kPlanRules.allowed) + ")");
      }
      continue;
    }
    bool is_via = false;
    PlanRow row = parse_row(fields, *columns, source_name, at, is_via);
    if (is_via) {
      if (pending_via) {
        throw FileError(source_name, pending_via->line,
                        "via row of '" + detail::printable(pending_via->point) +
                            "' is not followed by its location (a via row comes just before "
                            "the row with the same point)");
      }
      pending_via = std::move(row);
      continue;
    }
    if (pending_via) {
      if (pending_via->point != row.point || pending_via->config != row.config) {
        throw FileError(source_name, pending_via->line,
                        "via row of '" + detail::printable(pending_via->point) +
                            "' is not followed by its location (a via row comes just before "
                            "the row with the same point)");
      }
      row.via = PlanVia{pending_via->robot_m, std::move(pending_via->q_rad)};
      pending_via.reset();
    }
    const auto [it, inserted] = seen.emplace(std::pair{row.point, row.config.value_or(-1)}, at);
    if (!inserted) {
      throw FileError(source_name, at,
                      "point '" + detail::printable(row.point) +
                          "' is listed twice in the same configuration (first on line " +
                          std::to_string(it->second) + ")");
    }
    plan.rows.push_back(std::move(row));
  }
  if (pending_via) {
    throw FileError(source_name, pending_via->line,
                    "via row of '" + detail::printable(pending_via->point) +
                        "' is the last row: a via row comes just before its location's row");
  }
  if (!columns) {
    throw FileError(source_name, 0,
                    reader.line_number() == 0
                        ? "empty file (expected a header line and one row per location)"
                        : "no header line (the file holds only comments or blank lines)");
  }
  if (plan.rows.empty()) throw FileError(source_name, header_line, "header only: no locations");
  plan.n_joints = static_cast<int>(columns->joints.size());
  plan.has_config = columns->config != detail::PointColumns::kAbsent;
  return plan;
}

PlanFile read_plan_csv(const std::string& path) {
  std::ifstream in = open_input_file(path);
  return parse_plan_csv(in, path);
}

}  // namespace vrreg::io
