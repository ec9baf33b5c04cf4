// SPDX-License-Identifier: Apache-2.0
// vrreg report: one self-contained HTML page (Plotly inlined, works offline) with the paper's
// kinds of figures, either for a user's own cell (--model, --targets: evaluated as `evaluate`
// does, with a verdict in words) or for the paper's experiments (--reproduce DIR).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "measurement_input.hpp"
#include "report_cli.hpp"
#include "strategy_cli.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/io/plan_csv.hpp"
#include "vrreg/report/cell_report.hpp"
#include "vrreg/report/monitor_history.hpp"
#include "vrreg/report/reproduce_report.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::cli {
namespace {

struct ReportArgs {
  std::string model;
  std::string targets;
  std::optional<int> config;
  InterpolationFlags interpolation;
  StrategyFlags strategy;
  std::optional<double> sigma_rep_mm;
  std::string reproduce;
  std::string plan;
  std::string history;
  std::string output;
  bool json = false;
};

// The cell page: the targets evaluated exactly as `vrreg evaluate` does.
report::ReportPage cell_page(const ReportArgs& args) {
  const RegistrationModel model = io::read_model_json(args.model);
  EvaluateOptions options;
  options.config = args.config;
  options.interpolation = args.interpolation.choice();
  apply_evaluate_flags(args.strategy, options);
  EvaluateResult evaluation;
  naming_file(args.model, [&] {
    evaluation = evaluate(model, read_measurements(args.targets), options);
  });
  std::optional<double> sigma_rep;
  if (args.sigma_rep_mm) sigma_rep = units::mm_to_m(*args.sigma_rep_mm);
  const report::CellReportInput input{model, evaluation, args.model, args.targets, sigma_rep};
  const report::CellAnalysis analysis = report::analyze_cell(input);
  return report::cell_report_page(input, analysis);
}

void run_report(const ReportArgs& args) {
  const bool cell = !args.model.empty() || !args.targets.empty();
  VRREG_THROW_UNLESS(cell != !args.reproduce.empty(),
                     "give either --model and --targets (your cell) or --reproduce DIR "
                     "(the paper's experiments)");
  VRREG_THROW_UNLESS(!cell || (!args.model.empty() && !args.targets.empty()),
                     "a cell report needs both --model and --targets");
  VRREG_THROW_UNLESS(cell || args.history.empty(),
                     "--history goes with a cell report (--model and --targets)");
  report::ReportPage page;
  if (cell) {
    page = cell_page(args);
    if (!args.plan.empty()) {
      page.sections.push_back(report::plan_section(io::read_plan_csv(args.plan), args.plan));
    }
    if (!args.history.empty()) {
      page.sections.push_back(
          report::monitor_history_section(io::read_check_history(args.history), args.history));
    }
    write_report_html(page, args.output);
  } else {
    page = write_reproduce_report(args.reproduce, args.plan, args.output);
  }
  if (args.json) {
    nlohmann::json j;
    j["output"] = args.output;
    j["charts"] = page.figure_count();
    nlohmann::json verdict = nlohmann::json::array();
    for (const auto& v : page.verdict) verdict.push_back(v.text);
    j["verdict"] = verdict;
    print_json(j);
    return;
  }
  std::printf("report with %d charts written to %s (one file, opens offline in a browser)\n",
              page.figure_count(), args.output.c_str());
  for (const auto& v : page.verdict) std::printf("  - %s\n", v.text.c_str());
}

void add_report_command(CLI::App& app) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "write one self-contained HTML report (charts work offline): for your cell "
      "(--model, --targets) or for the paper's experiments (--reproduce DIR)");
  add_input_option(*cmd, "--model", args->model, "model JSON written by 'vrreg register -o'");
  add_input_option(*cmd, "--targets", args->targets,
                   "measurement CSV; its target rows are evaluated");
  cmd->add_option("--config", args->config,
                  "use only target rows with this configuration label (default: the model's)");
  args->interpolation.add_to(*cmd);
  args->strategy.add_to(*cmd, false);
  cmd->add_option("--sigma-rep-mm", args->sigma_rep_mm,
                  "robot repeatability in mm, for sigma_noise and rho (UR5 0.1, LWR 4+ 0.05)")
      ->check(CLI::NonNegativeNumber);
  add_input_directory_option(
      *cmd, "--reproduce", args->reproduce,
      "directory written by 'vrreg reproduce --out DIR' (reads DIR/reproduce.json)",
      "reproduce.json");
  add_input_option(*cmd, "--history", args->history,
                   "with --model: the cell's check history (vrreg check --history) as a section");
  add_input_option(*cmd, "--plan", args->plan,
                   "plan CSV from 'vrreg plan': adds its fiducial layout "
                   "(paper Fig. 16)");
  add_output_option(*cmd, "-o,--output", args->output, "the HTML file to write")->required();
  cmd->add_flag("--json", args->json, "print one JSON object (output, charts, verdict)");
  cmd->callback([args] { run_report(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(35, add_report_command);

}  // namespace vrreg::cli
