// SPDX-License-Identifier: Apache-2.0
#pragma once
// Small helpers shared by the commands: millimetre formatting, option parsing glue.
#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "file_options.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/io/output_paths.hpp"
#include "vrreg/pipeline/interpolation_choice.hpp"

namespace vrreg::cli {

/// Command-line interpolation options: --interpolation and --cube-mm.
struct InterpolationFlags {
  std::string method;  ///< empty: keep the model's
  std::optional<double> cube_mm;
  bool refit = false;  ///< evaluate, correct: fit the corrector again
  bool exact = false;  ///< evaluate, correct: the field model itself, not its table
  bool extrapolate = false;  ///< evaluate, correct: correct outside the support too
  void add_to(CLI::App& command);
  /// --refit, --exact and --extrapolate, for the commands that use a model's corrector.
  void add_corrector_flags_to(CLI::App& command);
  /// As the library's override of a model's stored settings.
  [[nodiscard]] InterpolationChoice choice() const;
  /// Register's settings: the defaults with these on top.
  [[nodiscard]] InterpolationSettings settings() const;
};

/// Runs `run`; an InputError that names no file (degenerate geometry, what a model cannot do)
/// becomes a FileError naming `path`, the file the command was given it from.
template <typename F>
void naming_file(const std::string& path, F&& run) {
  try {
    run();
  } catch (const FileError&) {
    throw;  // names its file (and line) already
  } catch (const InputError& e) {
    throw FileError(path, 0, e.what());
  }
}

/// Adds an output-file option (FileRole::kOutput): when given, its name may not be empty (an empty
/// one would quietly write nothing).
CLI::Option* add_output_option(CLI::App& command, const std::string& names, std::string& path,
                               const std::string& help);

/// Adds an input-file option (FileRole::kInput): when given, its value may not be empty (an
/// empty one would be opened as ""), and the usage error names the option.
CLI::Option* add_input_option(CLI::App& command, const std::string& names, std::string& path,
                              const std::string& help);

/// Adds a robot option: a built-in robot's name, or a robot file (then an input).
CLI::Option* add_robot_option(CLI::App& command, const std::string& names, std::string& robot,
                              const std::string& help);

/// Adds an option naming a directory the command reads `file` from (the input is DIR/file).
CLI::Option* add_input_directory_option(CLI::App& command, const std::string& names,
                                        std::string& dir, const std::string& help,
                                        const std::string& file);

/// Refuses a negative seed: CLI11 would read "-1" into an unsigned seed as 2^64 - 1.
CLI::Validator non_negative_seed();

/// Adds a seed option (an unsigned integer or an optional one) that refuses negative values.
template <typename T>
CLI::Option* add_seed_option(CLI::App& command, const std::string& names, T& seed,
                             const std::string& help) {
  return command.add_option(names, seed, help)->check(non_negative_seed());
}

/// Prints JSON to stdout, two-space indented, with a final newline.
void print_json(const nlohmann::json& j);

}  // namespace vrreg::cli
