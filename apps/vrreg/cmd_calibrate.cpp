// SPDX-License-Identifier: Apache-2.0
// vrreg calibrate-testbeds: simulate the paper's datasets for a range of seeds, run the pipeline
// and compare the medians with the acceptance bands (docs/testbed-calibration.md).
#include <chrono>
#include <cstdio>
#include <memory>
#include <sstream>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/experiments/testbed_calibration.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/robot_io/error_model_file.hpp"

namespace vrreg::cli {
namespace {

struct CalibrateArgs {
  std::string seeds = "1-10";
  std::string ur5_errors;
  std::string lwr4_errors;
  std::string only;
  std::string output;
  bool check = false;
};

// "1-10", "3", "1,4,7-9".
std::vector<std::uint64_t> parse_seeds(const std::string& text) {
  std::vector<std::uint64_t> seeds;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ',')) {
    const std::size_t dash = part.find('-');
    try {
      std::size_t used = 0;
      const std::uint64_t first = std::stoull(part.substr(0, dash), &used);
      VRREG_THROW_UNLESS(used == (dash == std::string::npos ? part.size() : dash), "");
      std::uint64_t last = first;
      if (dash != std::string::npos) {
        last = std::stoull(part.substr(dash + 1), &used);
        VRREG_THROW_UNLESS(used == part.size() - dash - 1 && last >= first && last - first < 10000,
                           "");
      }
      // Counted, not compared with `last`: a range ending at 2^64 - 1 would never end.
      for (std::uint64_t k = 0; k <= last - first; ++k) seeds.push_back(first + k);
    } catch (const std::exception&) {
      VRREG_THROW_UNLESS(false, "--seeds: cannot read '" << part << "' (use e.g. 1-10 or 1,3,5-7)");
    }
  }
  VRREG_THROW_UNLESS(!seeds.empty(), "--seeds: no seeds in '" << text << "'");
  return seeds;
}

void run_calibrate(const CalibrateArgs& args) {
  experiments::CalibrationOptions options;
  options.seeds = parse_seeds(args.seeds);
  options.ur5 = args.only.empty() || args.only == "ur5";
  options.lwr4 = args.only.empty() || args.only == "lwr4";
  if (!args.ur5_errors.empty()) {
    options.ur5_errors = io::read_error_model_file(args.ur5_errors, simulation::ur5_testbed());
  }
  if (!args.lwr4_errors.empty()) {
    options.lwr4_errors = io::read_error_model_file(args.lwr4_errors, simulation::lwr4_testbed());
  }
  const auto start = std::chrono::steady_clock::now();
  const experiments::CalibrationReport report = experiments::run_testbed_calibration(options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string md = experiments::format_calibration_markdown(report);
  if (!args.output.empty()) io::write_file_atomically(args.output, md);
  std::fputs(md.c_str(), stdout);
  const bool pass = experiments::calibration_passes(report);
  std::printf("%zu seeds in %.1f s: %s\n", options.seeds.size(), seconds,
              pass ? "all acceptance bands met" : "some acceptance bands NOT met");
  VRREG_THROW_UNLESS(pass || !args.check, "calibration: acceptance bands not met");
}

void add_calibrate_command(CLI::App& app) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate-testbeds",
      "simulate the paper's datasets for several seeds and compare the pipeline's figures with "
      "the paper's (the table of docs/testbed-calibration.md)");
  cmd->group("Developer commands");
  not_a_file(*cmd, cmd->add_option("--seeds", args->seeds, "seeds, e.g. 1-10 or 1,3,5-7")
                       ->capture_default_str());
  add_input_option(*cmd, "--ur5-errors", args->ur5_errors, "error-model file for the UR5 test bed");
  add_input_option(*cmd, "--lwr4-errors", args->lwr4_errors,
                   "error-model file for the LWR test bed");
  not_a_file(*cmd, cmd->add_option("--only", args->only, "run one test bed only")
                       ->check(CLI::IsMember({"ur5", "lwr4"})));
  add_output_option(*cmd, "-o,--output", args->output, "also write the Markdown tables here");
  cmd->add_flag("--check", args->check, "exit with status 1 when a band is not met");
  cmd->callback([args] { run_calibrate(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(90, add_calibrate_command);

}  // namespace vrreg::cli
