// SPDX-License-Identifier: Apache-2.0
#pragma once
// Runs the built `vrreg` command and captures exit status, stdout and stderr.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace vrreg::testing {

struct CliResult {
  int status = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Runs `vrreg ARGS` through the shell (ARGS already quoted as needed), in directory `cwd` when
/// not empty, with `env` ("NAME=value ...") prepended to the command when not empty.
inline CliResult run_vrreg_in(const std::filesystem::path& cwd, const std::string& args,
                              const std::string& env = "");

/// Runs `vrreg ARGS` through the shell (ARGS already quoted as needed).
inline CliResult run_vrreg(const std::string& args) { return run_vrreg_in({}, args); }

inline CliResult run_vrreg_in(const std::filesystem::path& cwd, const std::string& args,
                              const std::string& env) {
  const auto dir = std::filesystem::temp_directory_path();
  static int counter = 0;
  const std::string tag = std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const auto out_path = dir / ("vrreg-cli-out-" + tag);
  const auto err_path = dir / ("vrreg-cli-err-" + tag);
  const std::string prefix = (cwd.empty() ? std::string() : "cd '" + cwd.string() + "' && ") +
                             (env.empty() ? "" : env + " ");
  const std::string command = prefix + "'" + VRREG_CLI_PATH + "' " + args + " >'" +
                              out_path.string() + "' 2>'" + err_path.string() + "' </dev/null";
  const int raw = std::system(command.c_str());
  CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = read_text(out_path);
  r.err = read_text(err_path);
  std::filesystem::remove(out_path);
  std::filesystem::remove(err_path);
  return r;
}

/// A fresh empty directory for one test's files.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("vrreg-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

/// The path in single quotes, for a shell command line (test paths hold no quotes).
inline std::string shell_quoted(const std::filesystem::path& path) {
  return "'" + path.string() + "'";
}

/// The example cell every quick start uses (examples/data/example-cell.csv).
inline const std::string kExampleCell =
    std::string(VRREG_SOURCE_DIR) + "/examples/data/example-cell.csv";

}  // namespace vrreg::testing
