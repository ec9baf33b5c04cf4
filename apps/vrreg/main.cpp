// SPDX-License-Identifier: Apache-2.0
// vrreg: the command line. Parses, calls the library, writes through io. The only place that
// catches exceptions and maps them to exit codes:
//   0 success, 1 bad input or a failed computation (one line on stderr), 2 usage error,
//   3 the command answered but found no solution (vrreg ik; one line on stderr),
//   10, 11, 12 vrreg check: the cell changed (sensor moved, robot drifted, a monitor point moved).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <exception>
#include <iostream>
#include <new>
#include <string>

#include "command_registry.hpp"
#include "file_options.hpp"
#include "option_flags.hpp"
#include "progress_bar.hpp"
#include "vrreg/config.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/io/atomic_write.hpp"

int main(int argc, char** argv) {
  // Ctrl-C or kill while an output is written leaves no temporary file behind.
  vrreg::io::remove_temporary_files_on_signal();
  // Long stages (a large cell's fit) show a bar, on a terminal only: files and pipes never see it.
  vrreg::cli::install_terminal_progress();
  CLI::App app{
      "vrreg: point-based vision-robot registration with Restoration of the Rigid Body "
      "Condition (RRBC).\nLengths are printed in mm. Run 'vrreg COMMAND --help' for a command.",
      "vrreg"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "vrreg " VRREG_VERSION_STRING);
  auto& registry = vrreg::cli::command_registry();
  std::stable_sort(registry.begin(), registry.end(),
                   [](const auto& a, const auto& b) { return a.order < b.order; });
  for (const auto& entry : registry) entry.setup(app);
  // Before any command runs: no output of it may be, or link to, one of its inputs.
  app.parse_complete_callback([&app] {
    for (const CLI::App* command : app.get_subcommands()) vrreg::cli::check_command_files(*command);
  });

  // CLI11 would answer `vrreg serve --help` with the main help and exit 0, as if `serve` were an
  // argument of --help: a word before any command that names no command is a usage error.
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-') continue;
    const auto named = [&word](CLI::App* command) { return command->check_name(word); };
    if (app.get_subcommands(named).empty()) {
      std::cerr << "vrreg: usage error: unknown command '" << word << "' (see vrreg --help)\n";
      return 2;
    }
    break;
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // One line (CLI11's own adds a second): what was wrong, and where help is.
    std::string message = e.what();
    std::replace(message.begin(), message.end(), '\n', ' ');
    std::string help = "vrreg --help";
    for (const CLI::App* command : app.get_subcommands())
      help = "vrreg " + command->get_name() + " --help";
    std::cerr << "vrreg: usage error: " << message << " (see " << help << ")\n";
    return 2;
  } catch (const vrreg::cli::CellChanged& e) {
    std::cout.flush();
    return e.status;
  } catch (const vrreg::cli::NoSolution& e) {
    std::cout.flush();
    std::cerr << "vrreg: " << e.what() << "\n";
    return 3;
  } catch (const std::bad_alloc&) {
    std::cerr << "vrreg: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "vrreg: error: " << vrreg::cli::with_flags(e.what()) << "\n";
    return 1;
  }
  return 0;
}
