#include "cli_support.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::cli {

nlohmann::json json_mm3(const Eigen::Vector3d& metres) {
  return {units::m_to_mm(metres[0]), units::m_to_mm(metres[1]), units::m_to_mm(metres[2])};
}

void InterpolationFlags::add_to(CLI::App& command) {
  command
      .add_option("--interpolation", method,
                  "how corrections reach targets: auto (grid if the fiducials hold a complete "
                  "grid, else scattered), grid, scattered, octuplet")
      ->check(CLI::IsMember({"auto", "grid", "scattered", "octuplet"}));
  command
      .add_option("--cube-mm", cube_mm,
                  "octuplet cube edge in mm (fiducials at the 8 corners around each target)")
      ->check(CLI::PositiveNumber);
}

InterpolationChoice InterpolationFlags::choice() const {
  InterpolationChoice c;
  if (!method.empty()) c.method = parse_interpolation_method(method);
  if (cube_mm) c.cube_edge_m = units::mm_to_m(*cube_mm);
  return c;
}

InterpolationSettings InterpolationFlags::settings() const { return choice().apply({}); }

void print_json(const nlohmann::json& j) { std::cout << j.dump(2) << "\n"; }

}  // namespace vrreg::cli
