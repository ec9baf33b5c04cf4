// vrreg simulate: the paper's datasets acquired on a simulated test bed (UR5: A1, A2, B; KUKA
// LWR 4+: grid), written as a measurement CSV. Same seed, same bytes.
#include <cstdio>
#include <memory>

#include "command_registry.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/io/error_model_file.hpp"
#include "vrreg/io/simulation_csv.hpp"
#include "vrreg/simulation/acquisition.hpp"

namespace vrreg::cli {
namespace {

struct SimulateArgs {
  std::string testbed;
  std::string dataset;
  std::uint64_t seed = 1;
  std::string errors;
  std::string output;
  std::string write_errors;
};

void run_simulate(const SimulateArgs& args) {
  const simulation::Testbed testbed = simulation::testbed_by_name(args.testbed);
  simulation::SimulationOptions options;
  options.seed = args.seed;
  if (!args.errors.empty()) options.errors = io::read_error_model_file(args.errors, testbed);
  if (!args.write_errors.empty()) {
    io::write_error_model_file(args.write_errors, options.errors.value_or(testbed.default_errors),
                               testbed.name);
    std::printf("error model of test bed %s written to %s\n", testbed.name.c_str(),
                args.write_errors.c_str());
  }
  if (args.output.empty()) {
    VRREG_THROW_UNLESS(!args.write_errors.empty(),
                       "simulate: nothing to do: give -o FILE.csv (and a DATASET)");
    return;
  }
  VRREG_THROW_UNLESS(!args.dataset.empty(),
                     "simulate: give a DATASET (ur5: A1, A2 or B; lwr4: grid)");
  const simulation::Dataset dataset = simulation::parse_dataset(args.dataset);
  simulation::check_dataset(testbed.kind, dataset);
  const simulation::SimulatedDataset data = simulation::simulate_dataset(testbed, dataset, options);
  io::write_simulated_dataset_csv(args.output, data);
  std::size_t targets = 0;
  for (const auto& location : data.locations) targets += location.role == Role::kTarget ? 1 : 0;
  std::printf(
      "simulated %s %s with seed %llu%s\n", testbed.name.c_str(), simulation::to_string(dataset),
      static_cast<unsigned long long>(args.seed),
      args.errors.empty() ? " (default errors)" : (" (errors from " + args.errors + ")").c_str());
  std::printf("  %zu locations (%zu fiducials, %zu targets), %zu visits, %zu readings\n",
              data.locations.size(), data.locations.size() - targets, targets, data.visits.size(),
              data.readings.size());
  std::printf("  written to %s\n", args.output.c_str());
}

void add_simulate_command(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "acquire one of the paper's datasets on a simulated test bed (ur5: A1, A2, B; "
      "lwr4: grid) and write it as a measurement CSV");
  cmd->add_option("TESTBED", args->testbed, "ur5 or lwr4")->required();
  cmd->add_option("DATASET", args->dataset, "ur5: A1, A2 or B; lwr4: grid");
  cmd->add_option("--seed", args->seed,
                  "draws the robot's errors and the noise; the same seed gives the same file")
      ->capture_default_str();
  cmd->add_option("--errors", args->errors,
                  "error-model file (JSON or YAML) over the test bed's defaults; see "
                  "--write-errors");
  cmd->add_option("-o,--output", args->output, "measurement CSV to write");
  cmd->add_option("--write-errors", args->write_errors,
                  "write the error model in use (defaults, or --errors) to this JSON file");
  cmd->callback([args] { run_simulate(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(40, add_simulate_command);

}  // namespace vrreg::cli
