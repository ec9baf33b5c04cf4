// SPDX-License-Identifier: Apache-2.0
#pragma once
// Every option that can name a file says whether the command reads or writes it. main runs one
// check for every command before the command starts: no output may be, or link to, an input, nor
// be another output. A role is declared where the option is, so a new option cannot be missed
// (tests/cli/file_option_roles_test.cpp fails for a text option without one).
#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace vrreg::cli {

enum class FileRole {
  kInput,            ///< read (a robot option's value only when it is not a built-in name)
  kOutput,           ///< written or appended to
  kOutputDirectory,  ///< files are written inside it: no input may lie there
  kNotAFile,         ///< a name, an address, a time, a choice: never opened
};

/// The files an option names as the command will use them (none when not given).
using OptionPaths = std::function<std::vector<std::string>()>;

struct FileOption {
  const CLI::App* command = nullptr;
  const CLI::Option* option = nullptr;
  FileRole role = FileRole::kNotAFile;
  std::string label;  ///< as errors name it: "-o", "--model"
  OptionPaths paths;
};

/// Records `option` of `command` with its role; returns `option`. `paths` may be empty for
/// kNotAFile. The record lives as long as the process: `command` and what `paths` reads must too.
CLI::Option* declare_file_role(CLI::App& command, CLI::Option* option, FileRole role,
                               OptionPaths paths = {});

/// Declares a text option that names no file.
CLI::Option* not_a_file(CLI::App& command, CLI::Option* option);

/// The role declared for `option`, if any.
std::optional<FileRole> declared_file_role(const CLI::Option* option);

/// Throws FileError when an output of `command`, as parsed, is one of its inputs or another
/// output (io::check_outputs_are_not_inputs), or an input lies in an output directory.
void check_command_files(const CLI::App& command);

}  // namespace vrreg::cli
