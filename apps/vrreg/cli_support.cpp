#include "cli_support.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::cli {

std::string mm(double metres, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, units::m_to_mm(metres));
  return buf;
}

std::string mm3(const Eigen::Vector3d& metres, int decimals) {
  return "[" + mm(metres[0], decimals) + ", " + mm(metres[1], decimals) + ", " +
         mm(metres[2], decimals) + "]";
}

nlohmann::json json_mm3(const Eigen::Vector3d& metres) {
  return {units::m_to_mm(metres[0]), units::m_to_mm(metres[1]), units::m_to_mm(metres[2])};
}

void InterpolationFlags::add_to(CLI::App& command) {
  command.add_option("--interpolation", method,
                     "how corrections reach targets: auto (grid if the fiducials hold a complete "
                     "grid, else scattered), grid, scattered, octuplet")
      ->check(CLI::IsMember({"auto", "grid", "scattered", "octuplet"}));
  command.add_option("--cube-mm", cube_mm,
                     "octuplet cube edge in mm (fiducials at the 8 corners around each target)")
      ->check(CLI::PositiveNumber);
}

InterpolationSettings InterpolationFlags::apply(InterpolationSettings stored) const {
  if (!method.empty()) stored.method = parse_interpolation_method(method);
  if (cube_mm) {
    stored.cube_edge_m = units::mm_to_m(*cube_mm);
    if (method.empty()) stored.method = InterpolationMethod::kOctuplet;
  }
  VRREG_THROW_UNLESS(stored.method != InterpolationMethod::kOctuplet || stored.cube_edge_m > 0.0,
                     "--interpolation octuplet needs --cube-mm EDGE");
  return stored;
}

std::vector<std::size_t> select_rows(const MeasurementSet& set, Role role,
                                     std::optional<int> config) {
  std::vector<std::size_t> rows = set.select(role, config);
  const std::string what = role == Role::kFiducial ? "fiducial" : "target";
  // FileError: the message names the file once, and the commands pass it on unchanged.
  if (config && !set.has_config) {
    throw io::FileError(set.source, 0,
                        "--config " + std::to_string(*config) + " given but the file has no config column");
  }
  if (rows.empty()) {
    throw io::FileError(set.source, 0,
                        "no " + what + " rows" +
                            (config ? " with config " + std::to_string(*config) : std::string()));
  }
  return rows;
}

std::vector<std::size_t> source_lines(const MeasurementSet& set,
                                      const std::vector<std::size_t>& rows) {
  std::vector<std::size_t> lines;
  lines.reserve(rows.size());
  for (std::size_t i : rows) lines.push_back(set.locations[i].source_line);
  return lines;
}

void print_json(const nlohmann::json& j) { std::cout << j.dump(2) << "\n"; }

}  // namespace vrreg::cli
