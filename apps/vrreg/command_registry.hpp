// SPDX-License-Identifier: Apache-2.0
#pragma once
// Each command lives in its own cmd_<name>.cpp and registers itself here, so adding a command
// touches no other file. `order` fixes the position in --help.
#include <CLI/CLI.hpp>
#include <functional>
#include <stdexcept>
#include <vector>

namespace vrreg::cli {

using CommandSetup = std::function<void(CLI::App& app)>;

struct CommandEntry {
  int order;
  CommandSetup setup;
};

std::vector<CommandEntry>& command_registry();

/// Thrown by a command after it printed its answer when that answer is a refusal (vrreg ik found
/// no solution): main prints the message as one line on stderr and exits with status 3.
class NoSolution : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown by `vrreg check` after it printed its answer when the cell changed: main exits with
/// `status` (10 the sensor moved, 11 the robot drifted, 12 one monitor point moved, 13 noisier
/// today) and prints nothing more, so a cell controller can act on the status alone.
class CellChanged : public std::runtime_error {
 public:
  CellChanged(int exit_status, const std::string& what)
      : std::runtime_error(what), status(exit_status) {}
  int status;
};

struct CommandRegistrar {
  CommandRegistrar(int order, CommandSetup setup) {
    command_registry().push_back({order, std::move(setup)});
  }
};

}  // namespace vrreg::cli

#define VRREG_CONCAT_INNER(a, b) a##b
#define VRREG_CONCAT(a, b) VRREG_CONCAT_INNER(a, b)
/// Registers a command set-up function: VRREG_REGISTER_COMMAND(10, add_register_command);
/// __COUNTER__, not __LINE__: a unity build puts several cmd_*.cpp in one translation unit.
#define VRREG_REGISTER_COMMAND(order, fn) \
  static const ::vrreg::cli::CommandRegistrar VRREG_CONCAT(vrreg_registrar_, __COUNTER__)(order, fn)
