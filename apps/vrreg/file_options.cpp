// SPDX-License-Identifier: Apache-2.0
#include "file_options.hpp"

#include <filesystem>

#include "vrreg/io/file_error.hpp"
#include "vrreg/io/output_paths.hpp"

namespace vrreg::cli {
namespace {

std::vector<FileOption>& file_option_registry() {
  static std::vector<FileOption> registry;
  return registry;
}

// As the messages have always named options: the short name first ("-o", not "--output").
std::string option_label(const CLI::Option& option) {
  if (!option.get_snames().empty()) return "-" + option.get_snames().front();
  if (!option.get_lnames().empty()) return "--" + option.get_lnames().front();
  return option.get_name();
}

// Whether `path` is `dir` or lies under it, links and `..` resolved.
bool lies_in(const std::string& path, const std::string& dir) {
  std::error_code ep;
  std::error_code ed;
  const auto p = std::filesystem::weakly_canonical(path, ep);
  const auto d = std::filesystem::weakly_canonical(dir, ed);
  if (ep || ed) return false;
  auto pi = p.begin();
  for (auto di = d.begin(); di != d.end(); ++di, ++pi) {
    if (di->empty()) continue;  // a trailing separator
    if (pi == p.end() || *pi != *di) return false;
  }
  return true;
}

}  // namespace

CLI::Option* declare_file_role(CLI::App& command, CLI::Option* option, FileRole role,
                               OptionPaths paths) {
  file_option_registry().push_back(
      {&command, option, role, option_label(*option), std::move(paths)});
  return option;
}

CLI::Option* not_a_file(CLI::App& command, CLI::Option* option) {
  return declare_file_role(command, option, FileRole::kNotAFile);
}

std::optional<FileRole> declared_file_role(const CLI::Option* option) {
  for (const FileOption& f : file_option_registry()) {
    if (f.option == option) return f.role;
  }
  return std::nullopt;
}

void check_command_files(const CLI::App& command) {
  std::vector<io::CommandPath> inputs;
  std::vector<io::CommandPath> outputs;
  std::vector<io::CommandPath> directories;
  for (const FileOption& f : file_option_registry()) {
    if (f.command != &command || !f.paths) continue;
    for (const std::string& path : f.paths()) {
      if (path.empty()) continue;
      switch (f.role) {
        case FileRole::kInput:
          inputs.push_back({f.label, path});
          break;
        case FileRole::kOutput:
          outputs.push_back({f.label, path});
          break;
        case FileRole::kOutputDirectory:
          directories.push_back({f.label, path});
          break;
        case FileRole::kNotAFile:
          break;
      }
    }
  }
  io::check_outputs_are_not_inputs(inputs, outputs);
  for (const io::CommandPath& dir : directories) {
    for (const io::CommandPath& in : inputs) {
      if (!lies_in(in.path, dir.path)) continue;
      throw io::FileError(dir.path, 0,
                          dir.option + " holds the input " + in.option + " '" + in.path +
                              "': refusing to write over it (nothing was written)");
    }
  }
}

}  // namespace vrreg::cli
