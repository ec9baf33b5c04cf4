// vrreg evaluate: the true accuracy of a registration on independent targets: TRE and RMS_T
// uncorrected and RRBC-corrected (Eq. 3, 4, 7, 8), gamma, N_bad and Delta TRE (section 5.1),
// following the model's Procedure 2 strategy (section 4.4, strategy_cli.hpp).
#include <cstdio>
#include <sstream>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "strategy_cli.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/metrics/improvement.hpp"

namespace vrreg::cli {
namespace {

struct EvaluateArgs {
  std::string model;
  std::string targets;
  std::optional<int> config;
  InterpolationFlags interpolation;
  StrategyFlags strategy;
  std::string per_target;
  bool json = false;
};

std::string per_target_csv(const MeasurementSet& set, const std::vector<std::size_t>& rows,
                           const TargetCorrection& c, const Eigen::VectorXd& unc,
                           const Eigen::VectorXd& cor) {
  std::ostringstream out;
  out.precision(10);
  out << "point,config,status,unc_tre_mm,cor_tre_mm,delta_tre_mm,"
         "corrected_robot_x_mm,corrected_robot_y_mm,corrected_robot_z_mm,"
         "correction_x_mm,correction_y_mm,correction_z_mm\n";
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Location& loc = set.locations[rows[k]];
    const auto n = static_cast<Eigen::Index>(k);
    out << loc.point << ',' << (loc.config ? std::to_string(*loc.config) : "") << ','
        << to_string(c.stencils[k].status) << ',' << units::m_to_mm(unc[n]) << ','
        << units::m_to_mm(cor[n]) << ',' << units::m_to_mm(cor[n] - unc[n]);
    for (int a = 0; a < 3; ++a) out << ',' << units::m_to_mm(c.corrected_robot_m(a, n));
    for (int a = 0; a < 3; ++a) out << ',' << units::m_to_mm(c.corrections_sensor_m(a, n));
    out << '\n';
  }
  return out.str();
}

void run_evaluate(const EvaluateArgs& args) {
  const RegistrationModel model = io::read_model_json(args.model);
  const int strategy = evaluate_strategy(args.strategy, model, args.model);
  MeasurementSet set = io::read_measurement_csv(args.targets);
  std::optional<planning::Strategy2Summary> relabelled;
  if (strategy == 2) {  // the targets take the labels of their own path, like the fiducials did
    planning::Strategy2Result r = relabel_file(set, joint_norm(args.strategy, &model));
    set = std::move(r.set);
    relabelled = r.summary;
  }
  // A model built for one configuration is evaluated on that configuration unless told otherwise.
  const std::optional<int> config = args.config ? args.config : model.config;
  VRREG_THROW_UNLESS(strategy != 1 || config,
                     args.model << ": --strategy 1 evaluates one configuration: give --config N");
  const std::vector<std::size_t> rows = select_rows(set, Role::kTarget, config);
  const Points3 targets_sensor = set.sensor_points(rows);
  const Points3 targets_robot = set.robot_points(rows);
  const InterpolationSettings settings = args.interpolation.apply(model.interpolation);

  const TargetCorrection c =
      strategy == 3
          ? correct_strategy3(model, set, rows, settings, joint_norm(args.strategy, &model))
          : correct_targets(model, targets_sensor, targets_robot, settings,
                                      source_lines(set, rows));
  // Flagged targets keep their uncorrected mapping: that is what `correct` would hand the robot.
  const Eigen::VectorXd unc = point_errors(c.uncorrected_robot_m, targets_robot);
  const Eigen::VectorXd cor = point_errors(c.corrected_robot_m, targets_robot);
  const ImprovementSummary s = summarize_improvement(unc, cor);

  if (!args.per_target.empty()) {
    io::write_file_atomically(args.per_target, per_target_csv(set, rows, c, unc, cor));
  }
  std::vector<std::string> bad;
  for (int n : s.bad_targets) bad.push_back(set.locations[rows[static_cast<std::size_t>(n)]].point);

  if (args.json) {
    nlohmann::json j;
    j["model"] = args.model;
    j["targets"] = args.targets;
    j["config"] = config ? nlohmann::json(*config) : nlohmann::json(nullptr);
    j["interpolation"] = to_string(c.method_used);
    j["layout"] = c.layout;
    if (c.method_used == InterpolationMethod::kOctuplet) {
      j["cube_mm"] = units::m_to_mm(settings.cube_edge_m);
    }
    j["n_targets"] = s.n_targets;
    j["n_flagged"] = c.n_flagged;
    j["unc_rms_t_mm"] = units::m_to_mm(s.unc_rms_t_m);
    j["cor_rms_t_mm"] = units::m_to_mm(s.cor_rms_t_m);
    j["gamma_percent"] = 100.0 * s.gamma;
    j["n_bad"] = s.n_bad;
    j["bad_targets"] = bad;
    j["unc_max_tre_mm"] = units::m_to_mm(unc.size() ? unc.maxCoeff() : 0.0);
    j["cor_max_tre_mm"] = units::m_to_mm(cor.size() ? cor.maxCoeff() : 0.0);
    add_strategy_json(j, model, relabelled);
    if (strategy == 1 && model.procedure2.strategy == 0) j["strategy"] = 1;
    print_json(j);
    return;
  }
  std::printf("evaluated %d targets from %s with model %s%s\n", s.n_targets, args.targets.c_str(),
              args.model.c_str(), config ? (" (config " + std::to_string(*config) + ")").c_str() : "");
  print_strategy(model, relabelled);
  std::printf("  interpolation                 %s: %s\n", to_string(c.method_used), c.layout.c_str());
  if (c.n_flagged > 0) {
    std::printf("  not correctable               %d targets (outside the fiducials; left uncorrected)\n",
                c.n_flagged);
  }
  std::printf("                                uncorrected  corrected (RRBC)\n");
  std::printf("  RMS_T                         %8s mm  %8s mm\n", mm(s.unc_rms_t_m).c_str(),
              mm(s.cor_rms_t_m).c_str());
  std::printf("  max TRE                       %8s mm  %8s mm\n",
              mm(unc.size() ? unc.maxCoeff() : 0.0).c_str(), mm(cor.size() ? cor.maxCoeff() : 0.0).c_str());
  std::printf("  gamma = (unc - cor) / unc     %.1f %%\n", 100.0 * s.gamma);
  std::printf("  N_bad (TRE got worse)         %d of %d", s.n_bad, s.n_targets);
  if (!bad.empty()) {
    std::printf(":");
    for (std::size_t k = 0; k < bad.size() && k < 10; ++k) std::printf(" %s", bad[k].c_str());
    if (bad.size() > 10) std::printf(" ...");
  }
  std::printf("\n");
  if (!args.per_target.empty()) std::printf("  per-target errors written to %s\n", args.per_target.c_str());
}

void add_evaluate_command(CLI::App& app) {
  auto args = std::make_shared<EvaluateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "evaluate", "measure a model's accuracy on targets measured in both frames: TRE and RMS_T "
                  "uncorrected and RRBC-corrected (paper Eq. 3, 4, 7, 8)");
  cmd->add_option("--model", args->model, "model JSON written by 'vrreg register -o'")->required();
  cmd->add_option("--targets", args->targets, "measurement CSV; its target rows are used")
      ->required();
  cmd->add_option("--config", args->config,
                  "use only target rows with this configuration label (default: the model's)");
  args->interpolation.add_to(*cmd);
  args->strategy.add_to(*cmd, false);
  cmd->add_option("--per-target", args->per_target, "write per-target errors (CSV, mm) here");
  cmd->add_flag("--json", args->json, "print one JSON object instead of the table");
  cmd->callback([args] { run_evaluate(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(20, add_evaluate_command);

}  // namespace vrreg::cli
