// SPDX-License-Identifier: Apache-2.0
#include "cli_support.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "option_flags.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/robots.hpp"

namespace vrreg::cli {

void InterpolationFlags::add_to(CLI::App& command) {
  CLI::Option* interpolation =
      command
          .add_option(
              "--interpolation", method,
              "how corrections reach targets. The paper's linear weights (Eq. 7): linear "
              "(grid if the fiducials hold a complete grid, else scattered; the default), "
              "grid, scattered, octuplet. Models of the whole field (docs/field-models.md): "
              "trilinear (finest lattice, empty nodes filled), kriging, rbf, joint (needs "
              "joints and --robot), auto (the lowest cross-validated error)")
          ->check(CLI::IsMember({"linear", "grid", "scattered", "octuplet", "trilinear", "kriging",
                                 "rbf", "joint", "auto"}));
  not_a_file(command, interpolation);
  command
      .add_option("--cube-mm", cube_mm,
                  "octuplet cube edge in mm (fiducials at the 8 corners around each target)")
      ->check(CLI::PositiveNumber);
}

void InterpolationFlags::add_corrector_flags_to(CLI::App& command) {
  command.add_flag("--refit", refit,
                   "fit the corrector again instead of using the one the model file holds (the "
                   "same numbers unless the fitting code changed)");
  command.add_flag("--exact", exact,
                   "kriging and rbf: correct with the field model itself, not its table (which "
                   "the model file holds, within 1/20 of the noise of it); slower");
  command.add_flag("--extrapolate", extrapolate,
                   "correct targets outside the method's support (grid, hull, fiducials' box, "
                   "joint ranges) too (status 'extrapolated': the correction at the support's "
                   "nearest point and half the field's trend from there, its sd widened for the "
                   "distance; docs/uncertainty.md); without it they are left uncorrected");
}

InterpolationChoice InterpolationFlags::choice() const {
  InterpolationChoice c;
  if (!method.empty()) c.method = parse_interpolation_method(method);
  if (cube_mm) c.cube_edge_m = units::mm_to_m(*cube_mm);
  return c;
}

InterpolationSettings InterpolationFlags::settings() const { return choice().apply({}); }

namespace {

CLI::Validator not_empty(const std::string& needs) {
  return {[needs](std::string& text) { return text.empty() ? "needs " + needs : std::string(); },
          ""};
}

}  // namespace

CLI::Option* add_output_option(CLI::App& command, const std::string& names, std::string& path,
                               const std::string& help) {
  CLI::Option* option = command.add_option(names, path, help)->check(not_empty("a file name"));
  return declare_file_role(command, option, FileRole::kOutput,
                           [&path] { return std::vector<std::string>{path}; });
}

CLI::Option* add_input_option(CLI::App& command, const std::string& names, std::string& path,
                              const std::string& help) {
  CLI::Option* option = command.add_option(names, path, help)->check(not_empty("a file name"));
  return declare_file_role(command, option, FileRole::kInput,
                           [&path] { return std::vector<std::string>{path}; });
}

CLI::Option* add_robot_option(CLI::App& command, const std::string& names, std::string& robot,
                              const std::string& help) {
  CLI::Option* option =
      command.add_option(names, robot, help)->check(not_empty("a robot name or file"));
  // A built-in name is no file, even when a file of that name happens to be there.
  return declare_file_role(command, option, FileRole::kInput, [&robot] {
    return kinematics::robot_by_name(robot) ? std::vector<std::string>{}
                                            : std::vector<std::string>{robot};
  });
}

CLI::Option* add_input_directory_option(CLI::App& command, const std::string& names,
                                        std::string& dir, const std::string& help,
                                        const std::string& file) {
  CLI::Option* option = command.add_option(names, dir, help)->check(not_empty("a directory name"));
  return declare_file_role(command, option, FileRole::kInput, [&dir, file] {
    return dir.empty() ? std::vector<std::string>{}
                       : std::vector<std::string>{(std::filesystem::path(dir) / file).string()};
  });
}

CLI::Validator non_negative_seed() {
  return {[](std::string& value) {
            const std::size_t first = value.find_first_not_of(" \t");
            return first != std::string::npos && value[first] == '-'
                       ? "seeds are whole numbers >= 0, got " + value
                       : std::string();
          },
          ""};
}

// Library text in a result (layouts, notes) names options as `name`: here, the flags.
void print_json(const nlohmann::json& j) { std::cout << with_flags(j.dump(2)) << "\n"; }

}  // namespace vrreg::cli
