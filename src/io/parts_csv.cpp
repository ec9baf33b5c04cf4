// SPDX-License-Identifier: Apache-2.0
#include "vrreg/io/parts_csv.hpp"

#include <fstream>
#include <optional>
#include <unordered_map>

#include "csv_fields.hpp"
#include "line_reader.hpp"
#include "point_columns.hpp"
#include "text_checks.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/input_file.hpp"

namespace vrreg::io {
namespace {

constexpr std::size_t kPartsMaxLineBytes = 1024 * 1024;
constexpr double kSamePositionM = 1e-9;

const detail::PointColumnRules kPartsRules{
    "parts file",
    "a parts file has point, robot_x_mm, robot_y_mm, robot_z_mm (or _m); a measurement CSV's "
    "role, sensor_*, config, repeat and q* columns are also accepted",
    false, true};

// True for a row that names a part point: no role column, or role `target`.
bool is_part_row(const std::vector<std::string_view>& fields, const detail::PointColumns& cols,
                 const std::string& source, std::size_t line) {
  if (cols.role == detail::PointColumns::kAbsent) return true;
  const std::string role = detail::to_lower(fields[static_cast<std::size_t>(cols.role)]);
  if (role == "target") return true;
  if (role == "fiducial") return false;
  throw FileError(source, line,
                  "role must be 'fiducial' or 'target', got '" +
                      detail::printable(fields[static_cast<std::size_t>(cols.role)]) + "'");
}

}  // namespace

std::vector<PartRecord> parse_parts_csv(std::istream& in, const std::string& source_name) {
  detail::LineReader reader(in, source_name, kPartsMaxLineBytes);
  std::string line;
  std::vector<std::string_view> fields;
  std::optional<detail::PointColumns> columns;
  std::size_t header_line = 0;
  std::size_t skipped = 0;
  std::vector<PartRecord> parts;
  std::unordered_map<std::string, std::size_t> index_of;
  while (reader.next(line)) {
    const std::string_view content = detail::trim(line);
    if (content.empty() || content.front() == '#') continue;
    detail::split_fields(line, fields);
    if (detail::all_fields_empty(fields)) continue;
    const std::size_t at = reader.line_number();
    if (!columns) {
      header_line = at;
      columns = detail::parse_point_columns(fields, source_name, at, kPartsRules);
      continue;
    }
    detail::check_field_count(fields, *columns, source_name, at);
    // Part points become plan labels: refused here, by line, not when the plan is written.
    std::string label =
        detail::plan_label(detail::parse_point_label(
                               fields[static_cast<std::size_t>(columns->point)], source_name, at),
                           "point", source_name, at);
    const std::array<double, 3> xyz = detail::parse_robot_m(fields, *columns, source_name, at);
    if (!is_part_row(fields, *columns, source_name, at)) {
      ++skipped;
      continue;
    }
    const Eigen::Vector3d robot_m(xyz[0], xyz[1], xyz[2]);
    const auto [it, inserted] = index_of.emplace(label, parts.size());
    if (inserted) {
      parts.push_back({std::move(label), robot_m, at});
    } else if ((parts[it->second].robot_m - robot_m).cwiseAbs().maxCoeff() > kSamePositionM) {
      throw FileError(source_name, at,
                      "part point '" + detail::printable(it->first) +
                          "' has another position than on line " +
                          std::to_string(parts[it->second].line));
    }
  }
  if (!columns) {
    throw FileError(source_name, 0,
                    reader.line_number() == 0
                        ? "empty file (expected a header line and one row per part point)"
                        : "no header line (the file holds only comments or blank lines)");
  }
  if (parts.empty()) {
    throw FileError(source_name, header_line,
                    skipped > 0 ? "no part points: every row is a fiducial (part points are the "
                                  "rows with role 'target')"
                                : "header only: the file has no part points");
  }
  return parts;
}

std::vector<PartRecord> read_parts_csv(const std::string& path) {
  std::ifstream in = open_input_file(path);
  return parse_parts_csv(in, path);
}

}  // namespace vrreg::io
