// SPDX-License-Identifier: Apache-2.0
#include <cmath>

#include "csv_fields.hpp"
#include "text_checks.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/plan_csv.hpp"

namespace vrreg::io {
namespace {

void check_label(const std::string& label, const char* what, std::size_t row, bool may_be_empty) {
  if (label.empty()) {
    VRREG_THROW_UNLESS(may_be_empty, "plan row " << row << ": empty " << what << " label");
    return;
  }
  VRREG_THROW_UNLESS(label.find_first_of(",\"\r\n") == std::string::npos && label.front() != '#' &&
                         detail::trim(label).size() == label.size(),
                     "plan row " << row << ": " << what << " label '" << label
                                 << "' cannot be written (comma, quote, newline, leading '#' or "
                                    "surrounding spaces)");
  const auto problem = detail::find_non_text(label);
  VRREG_THROW_UNLESS(!problem, "plan row " << row << ": " << what << " label: " << *problem);
}

void append_number(std::string& out, double value, std::size_t row) {
  VRREG_THROW_UNLESS(std::isfinite(value), "plan row " << row << ": non-finite number");
  out += ',';
  out += detail::format_double(value);
}

}  // namespace

std::string format_plan_csv(const std::vector<PlanRow>& rows,
                            const std::vector<std::string>& comments) {
  VRREG_THROW_UNLESS(!rows.empty(), "plan: no rows to write");
  const PlanRow& first = rows.front();
  std::string out;
  for (const std::string& comment : comments) {
    std::size_t start = 0;
    for (;;) {
      const std::size_t newline = comment.find('\n', start);
      const std::string line =
          comment.substr(start, newline == std::string::npos ? std::string::npos : newline - start);
      const auto problem = detail::find_non_text(line);
      VRREG_THROW_UNLESS(!problem, "plan comment line: " << *problem);
      out += line.empty() ? "#\n" : "# " + line + "\n";
      if (newline == std::string::npos) break;
      start = newline + 1;
    }
  }
  out += "point,role,part,robot_x_mm,robot_y_mm,robot_z_mm";
  if (first.config) out += ",config";
  for (std::size_t k = 0; k < first.q_rad.size(); ++k) out += ",q" + std::to_string(k + 1) + "_rad";
  out += '\n';
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PlanRow& r = rows[i];
    check_label(r.point, "point", i, false);
    check_label(r.part, "part", i, true);
    VRREG_THROW_UNLESS(r.config.has_value() == first.config.has_value(),
                       "plan row " << i << ": config given for some rows but not all");
    VRREG_THROW_UNLESS(r.q_rad.size() == first.q_rad.size(),
                       "plan row " << i << " has " << r.q_rad.size() << " joint angles, row 0 has "
                                   << first.q_rad.size());
    if (r.via) {  // its own row just before, same label: moved to, never measured
      VRREG_THROW_UNLESS(r.via->q_rad.size() == first.q_rad.size(),
                         "plan row " << i << ": its via point has " << r.via->q_rad.size()
                                     << " joint angles, row 0 has " << first.q_rad.size());
      out += r.point + ",via," + r.part;
      for (int axis = 0; axis < 3; ++axis) {
        append_number(out, units::m_to_mm(r.via->robot_m(axis)), i);
      }
      if (r.config) out += "," + std::to_string(*r.config);
      for (const double q : r.via->q_rad) append_number(out, q, i);
      out += '\n';
    }
    out += r.point;
    out += ',';
    out += to_string(r.role);
    out += ',';
    out += r.part;
    for (int axis = 0; axis < 3; ++axis) append_number(out, units::m_to_mm(r.robot_m(axis)), i);
    if (r.config) out += "," + std::to_string(*r.config);
    for (const double q : r.q_rad) append_number(out, q, i);
    out += '\n';
  }
  return out;
}

void write_plan_csv(const std::string& path, const std::vector<PlanRow>& rows,
                    const std::vector<std::string>& comments) {
  write_file_atomically(path, format_plan_csv(rows, comments));
}

}  // namespace vrreg::io
