// SPDX-License-Identifier: Apache-2.0
// vrreg snippet: the robot-program function that asks `vrreg serve` for a correction (URScript
// for Universal Robots, KRL over EthernetKRL for KUKA), with its timeout and failure path.
#include <cstdio>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "serve/service.hpp"
#include "serve/snippets.hpp"
#include "serve/token.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/pipeline/prepared_corrector.hpp"

namespace vrreg::cli {
namespace {

struct SnippetArgs {
  std::string language;
  std::string model;
  std::string model_file;
  std::string connect = "127.0.0.1:30401";
  double timeout_s = 2.0;
  std::string token_file;
  std::string output;
  std::string eki_config;
  bool pose = false;
};

// The joints the served model's answers need: those of its robot when it is a joint-space model
// or has an applied lost-motion term (the joints and where the robot comes from), else 0.
int joints_the_model_needs(const std::string& path) {
  auto model = std::make_shared<const RegistrationModel>(io::read_model_json(path));
  const bool lost_motion = model->corrector && model->corrector->lost_motion() &&
                           model->corrector->lost_motion()->applied;
  const PreparedCorrector corrector(model, CorrectOptions{});
  if (corrector.joints_needed() > 0) return corrector.joints_needed();
  if (lost_motion && !model->fiducials.empty()) {
    return static_cast<int>(model->fiducials.front().q_rad.size());
  }
  return 0;
}

void run_snippet(const SnippetArgs& args) {
  serve::SnippetOptions o;
  o.model = args.model;
  if (!args.model_file.empty()) o.n_joints = joints_the_model_needs(args.model_file);
  const serve::Endpoint at = serve::parse_endpoint(args.connect);
  o.host = at.address;
  o.port = at.port;
  o.timeout_s = args.timeout_s;
  if (!args.token_file.empty()) o.token = serve::read_token(args.token_file);
  std::vector<io::OutputFile> outputs;
  if (args.language == "urscript") {
    if (!args.eki_config.empty()) throw InputError("--eki-config: for krl only");
    if (args.pose) {
      throw InputError(
          "--pose: for krl only (the URScript has vrreg_correct_pose beside "
          "vrreg_correct)");
    }
    outputs.push_back({args.output, serve::urscript_client(o)});
  } else {
    if (o.n_joints > 0 && args.pose) {
      throw InputError("--pose: the model's answers need the robot's joints, which "
                       "VRREG_CORRECT_POSE does not send (without --pose the file's function is "
                       "VRREG_CORRECT_JOINTS)");
    }
    if (args.eki_config.empty()) {
      throw InputError("--eki-config: krl needs the EthernetKRL configuration file (vrreg.xml)");
    }
    outputs.push_back({args.output, args.pose ? serve::krl_pose_client(o) : serve::krl_client(o)});
    outputs.push_back({args.eki_config, serve::krl_eki_config(o)});
  }
  io::write_files_atomically(outputs);
  for (const io::OutputFile& f : outputs) std::printf("wrote %s\n", f.path.c_str());
}

void add_snippet_command(CLI::App& app) {
  auto args = std::make_shared<SnippetArgs>();
  CLI::App* cmd = app.add_subcommand(
      "snippet",
      "Write the robot-program function that asks 'vrreg serve' for a correction (urscript: "
      "vrreg_correct(p) and vrreg_correct_pose(p); krl: VRREG_CORRECT, or VRREG_CORRECT_POSE "
      "with --pose, over EthernetKRL)");
  not_a_file(*cmd, cmd->add_option("language", args->language, "urscript or krl")
                       ->required()
                       ->check(CLI::IsMember({"urscript", "krl"})));
  not_a_file(*cmd, cmd->add_option("--model", args->model,
                                   "the served model's name (as 'vrreg serve' names it)")
                       ->required());
  add_input_option(*cmd, "--model-file", args->model_file,
                   "the served model's file: when its answers need the joints (a joint-space "
                   "model, or one with a lost-motion term), the URScript also has "
                   "vrreg_correct_joints(p, q, q_from), which sends the joints and those the "
                   "robot comes from");
  not_a_file(*cmd, cmd->add_option("--connect", args->connect,
                                   "the service's line-protocol address as the robot reaches it "
                                   "(default 127.0.0.1:30401)"));
  cmd->add_option("--timeout-s", args->timeout_s, "no answer within this: stop (default 2)")
      ->check(CLI::Range(0.001, 60.0));
  add_input_option(*cmd, "--token-file", args->token_file,
                   "the service's token (written into the program: keep the program private)");
  add_output_option(*cmd, "-o,--output", args->output, "write the function here")->required();
  add_output_option(*cmd, "--eki-config", args->eki_config,
                    "krl: write the EthernetKRL configuration (XML) here");
  cmd->add_flag("--pose", args->pose,
                "krl: VRREG_CORRECT_POSE, the whole FRAME (X, Y, Z, A, B, C), for models "
                "registered with rigid-body fiducials (file VRREG_CORRECT_POSE.src)");
  cmd->callback([args] { run_snippet(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(39, add_snippet_command);

}  // namespace vrreg::cli
