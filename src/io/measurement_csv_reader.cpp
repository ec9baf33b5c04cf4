// SPDX-License-Identifier: Apache-2.0
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>

#include "csv_fields.hpp"
#include "line_reader.hpp"
#include "location_accumulator.hpp"
#include "measurement_header.hpp"
#include "measurement_row.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/input_file.hpp"
#include "vrreg/core/progress.hpp"
#include "vrreg/io/measurement_csv.hpp"

namespace vrreg::io {
namespace {

// Blank lines, comment lines and rows of empty fields (spreadsheet exports) carry no data.
bool is_blank(const std::vector<std::string_view>& fields) {
  for (const std::string_view field : fields) {
    if (!field.empty()) return false;
  }
  return true;
}

// Bytes left in `in` from where it stands, or 0 when it cannot seek (a pipe).
std::int64_t bytes_left(std::istream& in) {
  const std::streampos here = in.tellg();
  if (here < 0) return 0;
  in.seekg(0, std::ios::end);
  const std::streampos end = in.tellg();
  in.seekg(here);
  return end < here ? 0 : static_cast<std::int64_t>(end - here);
}

// Per joint the sign of its last move before `row`: against from_q when the file gives it (0 for
// a joint that did not move), else along the rows (a joint that did not move keeps its sign;
// before the first row every sign is unknown, 0).
void set_approach_sign(detail::MeasurementRow& row, std::vector<double>& previous_q_rad,
                       Eigen::VectorXd& sign) {
  row.approach_sign.clear();
  if (row.q_rad.empty()) return;
  const Eigen::Map<const Eigen::VectorXd> q(row.q_rad.data(),
                                            static_cast<Eigen::Index>(row.q_rad.size()));
  if (!row.from_q_rad.empty()) {
    sign = Eigen::VectorXd::Zero(q.size());
    update_approach_sign(Eigen::Map<const Eigen::VectorXd>(row.from_q_rad.data(), q.size()), q,
                         sign);
  } else {
    if (sign.size() != q.size()) sign = Eigen::VectorXd::Zero(q.size());
    if (!previous_q_rad.empty()) {
      update_approach_sign(Eigen::Map<const Eigen::VectorXd>(previous_q_rad.data(), q.size()), q,
                           sign);
    }
    previous_q_rad = row.q_rad;
  }
  row.approach_sign.assign(sign.data(), sign.data() + sign.size());
}

}  // namespace

MeasurementSet parse_measurement_csv(std::istream& in, const std::string& source_name,
                                     const CsvReadOptions& options) {
  detail::LineReader reader(in, source_name, options.max_line_bytes);
  std::string line;
  std::vector<std::string_view> fields;
  std::optional<detail::MeasurementColumns> columns;
  std::optional<detail::LocationAccumulator> accumulator;
  std::size_t header_line = 0;
  detail::MeasurementRow row;
  // Approach directions (lost motion): from the from_q columns, or from the rows' order.
  std::vector<double> previous_q_rad;
  Eigen::VectorXd sign;
  // A file of 10^6 readings takes seconds: its bytes are the progress, reported per MiB.
  ProgressStage progress("reading " + std::filesystem::path(source_name).filename().string(),
                         bytes_left(in));
  std::int64_t unreported = 0;
  while (reader.next(line)) {
    unreported += static_cast<std::int64_t>(line.size()) + 1;
    if (unreported >= (std::int64_t{1} << 20)) {
      progress.advance(unreported);
      unreported = 0;
    }
    const std::string_view content = detail::trim(line);
    if (content.empty() || content.front() == '#') continue;
    detail::split_fields(line, fields);
    if (is_blank(fields)) continue;
    if (!columns) {
      header_line = reader.line_number();
      columns =
          detail::parse_measurement_header(fields, source_name, header_line, options.require_robot);
      accumulator.emplace(source_name, columns->has_robot(), options.robot_tolerance_m,
                          options.joint_tolerance_rad);
      continue;
    }
    detail::parse_measurement_row(fields, *columns, source_name, reader.line_number(), row);
    set_approach_sign(row, previous_q_rad, sign);
    accumulator->add(row, reader.line_number());
  }
  if (!columns) {
    throw FileError(source_name, 0,
                    reader.line_number() == 0
                        ? "empty file (expected a header line and data rows)"
                        : "no header line (the file holds only comments or blank lines)");
  }
  if (accumulator->rows() == 0) {
    throw FileError(source_name, header_line, "header only: the file has no data rows");
  }
  MeasurementSet set;
  set.source = source_name;
  set.locations = accumulator->take();
  set.n_joints = static_cast<int>(columns->joints.size());
  set.has_config = columns->config != detail::MeasurementColumns::kAbsent;
  set.has_repeat = columns->repeat != detail::MeasurementColumns::kAbsent;
  set.has_visit = columns->visit != detail::MeasurementColumns::kAbsent;
  set.approach = columns->joints.empty()         ? ApproachSource::kNone
                 : !columns->from_joints.empty() ? ApproachSource::kFromJoints
                                                 : ApproachSource::kRowOrder;
  return set;
}

MeasurementSet read_measurement_csv(const std::string& path, const CsvReadOptions& options) {
  std::ifstream in = open_input_file(path);
  return parse_measurement_csv(in, path, options);
}

}  // namespace vrreg::io
