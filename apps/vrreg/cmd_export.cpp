// SPDX-License-Identifier: Apache-2.0
// vrreg export: a model's T_robot_sensor (and marker offset) in the formats cells use: YAML
// (easy_handeye style, x y z qx qy qz qw in metres), a URDF fixed joint, or JSON with a 4x4 matrix.
#include <cstdio>
#include <memory>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/robot_io/model_export.hpp"

namespace vrreg::cli {
namespace {

struct ExportArgs {
  std::string model;
  std::string format;
  std::string output;
};

void run_export(const ExportArgs& args) {
  const RegistrationModel model = io::read_model_json(args.model);
  std::string text;
  naming_file(args.model,
              [&] { text = io::export_model(model, io::parse_export_format(args.format)); });
  if (args.output.empty()) {
    std::fputs(text.c_str(), stdout);
    return;
  }
  io::write_file_atomically(args.output, text);
  std::printf("T_robot_sensor%s of %s written to %s as %s\n",
              model.marker_offset ? " and the marker offset" : "", args.model.c_str(),
              args.output.c_str(), args.format.c_str());
}

void add_export_command(CLI::App& app) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "write a model's T_robot_sensor (sensor -> robot; and the marker offset) as YAML "
      "(easy_handeye style), a URDF joint or JSON with a 4x4 matrix, in metres");
  add_input_option(*cmd, "--model", args->model, "model JSON of vrreg register")->required();
  not_a_file(*cmd, cmd->add_option("--format", args->format, "yaml, urdf or json")
                       ->required()
                       ->check(CLI::IsMember({"yaml", "urdf", "json"})));
  add_output_option(*cmd, "-o,--output", args->output, "write here (default: standard output)");
  cmd->callback([args] { run_export(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(36, add_export_command);

}  // namespace vrreg::cli
