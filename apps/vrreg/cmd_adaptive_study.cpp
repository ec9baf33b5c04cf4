// SPDX-License-Identifier: Apache-2.0
// vrreg adaptive-study: the adaptive loop (plan-next -> simulate -> register -> plan-next) closed
// in simulation over seeds on the UR5 and LWR 4+ test beds, against Procedure 1's octuplets at
// each cube edge and the full grid: fiducials, readings, robot time, RMS_T (docs/adaptive.md).
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/experiments/adaptive_study.hpp"
#include "report_cli.hpp"
#include "vrreg/report/adaptive_report.hpp"

namespace vrreg::cli {
namespace {

namespace ex = experiments;

struct AdaptiveStudyArgs {
  ex::AdaptiveStudyOptions options;
  std::vector<std::uint64_t> seeds{3, 4, 5};
  std::vector<std::string> robots{"ur5", "lwr4"};
  std::optional<double> goal_sd_mm;
  double candidate_spacing_mm = 20.0;
  std::vector<double> cube_edges_mm;
  std::string interpolation = "joint";
  bool quick = false;
  bool json = false;
  std::string report;
};

std::string mm(double value_m, int digits = 3) {
  return std::isfinite(value_m) ? fmt::format("{:.{}f}", units::m_to_mm(value_m), digits) : "n/a";
}

std::string minutes(double seconds) { return fmt::format("{:.1f}", seconds / 60.0); }

std::string study_text(const ex::AdaptiveStudyResult& r) {
  std::string out;
  const ex::AdaptiveStudyOptions& o = r.options;
  out += fmt::format(
      "Adaptive planning study: robot time at {:g} s per move and {:g} s per reading (targets "
      "not counted); RMS_T corrected at the paper's targets (UR5: dataset B's {}, LWR 4+: its "
      "grid's {} in one arm configuration)\n\n",
      o.seconds_per_move, o.seconds_per_reading, r.n_targets.empty() ? 0 : r.n_targets.front(),
      r.n_targets.size() > 1 ? r.n_targets[1] : 0);
  out += fmt::format("{:<6} {:>5}  {:<22} {:>9} {:>9} {:>9} {:>10} {:>10}\n", "robot", "seed",
                     "plan", "fiducials", "readings", "time_min", "RMS_T_mm", "pred_mm");
  std::size_t fixed = 0;
  for (const ex::AdaptiveRun& a : r.adaptive) {
    for (const ex::AdaptiveBatch& b : a.batches) {
      out += fmt::format("{:<6} {:>5}  {:<22} {:>9} {:>9} {:>9} {:>10} {:>10}\n", a.robot, a.seed,
                         fmt::format("adaptive batch {}", b.batch), b.n_fiducials, b.n_readings,
                         minutes(b.robot_time_s), mm(b.measured_rms_t_m), mm(b.predicted_rms_t_m));
    }
    for (; fixed < r.fixed.size() && r.fixed[fixed].robot == a.robot && r.fixed[fixed].seed == a.seed;
         ++fixed) {
      const ex::FixedPlanRun& f = r.fixed[fixed];
      const std::string plan =
          f.plan == "grid" ? fmt::format("grid {:g} mm ({})", units::m_to_mm(f.cube_edge_m),
                                         f.interpolation)
                           : fmt::format("Procedure 1 d={:.2f} mm", units::m_to_mm(f.d_m));
      out += fmt::format("{:<6} {:>5}  {:<22} {:>9} {:>9} {:>9} {:>10} {:>10}\n", f.robot, f.seed,
                         plan, f.n_fiducials, f.n_readings, minutes(f.robot_time_s),
                         mm(f.rms_t_m), "");
    }
    out += fmt::format("{:<6} {:>5}  stopped: {} (corrected with {}, predicted by {})\n\n",
                       a.robot, a.seed, a.stop_reason, a.interpolation,
                       a.batches.empty() ? std::string("-") : a.batches.back().predicted_by);
  }
  out += "Done when (adaptive at STOP against Procedure 1 at d_min):\n";
  out += fmt::format("{:<6} {:>5} {:>10} {:>9} {:>10} {:>9} {:>9}  {}\n", "robot", "seed",
                     "P1_RMS_T", "P1_fid", "adapt_RMS", "adapt_fid", "meas/pred",
                     "reaches(<=1.1x) quarter honest(0.8-1.2)");
  for (const ex::AdaptiveVerdict& v : r.verdicts) {
    auto yes = [](bool b) { return b ? "yes" : "NO"; };
    out += fmt::format("{:<6} {:>5} {:>10} {:>9} {:>10} {:>9} {:>9.2f}  {} {} {}\n", v.robot, v.seed,
                       mm(v.procedure1_dmin_rms_t_m), v.procedure1_dmin_fiducials,
                       mm(v.adaptive_rms_t_m), v.adaptive_fiducials, v.measured_over_predicted,
                       yes(v.reaches), yes(v.quarter), yes(v.honest));
  }
  return out;
}

nlohmann::json number_mm(double value_m) {
  return std::isfinite(value_m) ? nlohmann::json(units::m_to_mm(value_m)) : nlohmann::json();
}

nlohmann::json study_json(const ex::AdaptiveStudyResult& r) {
  nlohmann::json adaptive = nlohmann::json::array();
  for (const ex::AdaptiveRun& a : r.adaptive) {
    nlohmann::json batches = nlohmann::json::array();
    for (const ex::AdaptiveBatch& b : a.batches) {
      batches.push_back({{"batch", b.batch},
                         {"n_fiducials", b.n_fiducials},
                         {"n_readings", b.n_readings},
                         {"robot_time_s", b.robot_time_s},
                         {"predicted_rms_t_mm", number_mm(b.predicted_rms_t_m)},
                         {"predicted_by", b.predicted_by},
                         {"prediction_note", b.prediction_note},
                         {"measured_rms_t_mm", number_mm(b.measured_rms_t_m)}});
    }
    const double ratio = a.measured_over_predicted();
    adaptive.push_back({{"robot", a.robot},
                        {"seed", a.seed},
                        {"stop_reason", a.stop_reason},
                        {"interpolation", a.interpolation},
                        {"measured_over_predicted",
                         std::isfinite(ratio) ? nlohmann::json(ratio) : nlohmann::json()},
                        {"batches", batches}});
  }
  nlohmann::json fixed = nlohmann::json::array();
  for (const ex::FixedPlanRun& f : r.fixed) {
    fixed.push_back({{"robot", f.robot},
                     {"seed", f.seed},
                     {"plan", f.plan},
                     {"cube_edge_mm", units::m_to_mm(f.cube_edge_m)},
                     {"d_mm", units::m_to_mm(f.d_m)},
                     {"interpolation", f.interpolation},
                     {"n_fiducials", f.n_fiducials},
                     {"n_readings", f.n_readings},
                     {"robot_time_s", f.robot_time_s},
                     {"rms_t_mm", number_mm(f.rms_t_m)}});
  }
  nlohmann::json verdicts = nlohmann::json::array();
  for (const ex::AdaptiveVerdict& v : r.verdicts) {
    verdicts.push_back({{"robot", v.robot},
                        {"seed", v.seed},
                        {"procedure1_dmin_rms_t_mm", number_mm(v.procedure1_dmin_rms_t_m)},
                        {"procedure1_dmin_fiducials", v.procedure1_dmin_fiducials},
                        {"goal_sd_mm", number_mm(v.goal_sd_m)},
                        {"adaptive_rms_t_mm", number_mm(v.adaptive_rms_t_m)},
                        {"adaptive_fiducials", v.adaptive_fiducials},
                        {"measured_over_predicted", std::isfinite(v.measured_over_predicted)
                                                        ? nlohmann::json(v.measured_over_predicted)
                                                        : nlohmann::json()},
                        {"reaches", v.reaches},
                        {"quarter", v.quarter},
                        {"honest", v.honest}});
  }
  return {{"seconds_per_move", r.options.seconds_per_move},
          {"seconds_per_reading", r.options.seconds_per_reading},
          {"batch", r.options.batch_size},
          {"min_relative_gain", r.options.min_relative_gain},
          {"adaptive", adaptive},
          {"fixed", fixed},
          {"verdicts", verdicts}};
}

void run_adaptive_study(const AdaptiveStudyArgs& args) {
  ex::AdaptiveStudyOptions o = args.options;
  o.seeds = args.seeds;
  o.robots = args.robots;
  if (args.goal_sd_mm) o.goal_sd_m = units::mm_to_m(*args.goal_sd_mm);
  o.candidate_spacing_m = units::mm_to_m(args.candidate_spacing_mm);
  for (const double a : args.cube_edges_mm) o.cube_edges_m.push_back(units::mm_to_m(a));
  o.interpolation = parse_interpolation_method(args.interpolation);
  if (args.quick) o = ex::quick_study_options(o);
  const ex::AdaptiveStudyResult result = ex::run_adaptive_study(o);
  if (!args.report.empty()) {
    (void)write_report_html(report::adaptive_study_page(result), args.report);
  }
  if (args.json) {
    print_json(study_json(result));
  } else {
    std::fputs(study_text(result).c_str(), stdout);
  }
}

void add_adaptive_study_command(CLI::App& app) {
  auto args = std::make_shared<AdaptiveStudyArgs>();
  ex::AdaptiveStudyOptions& o = args->options;
  CLI::App* cmd = app.add_subcommand(
      "adaptive-study",
      "close the adaptive loop (plan-next -> simulate -> register -> plan-next) on the "
      "simulated UR5 and LWR 4+ over seeds, against Procedure 1's octuplets at each cube edge and "
      "the full grid: fiducials, readings, robot time, RMS_T (docs/adaptive.md)");
  cmd->add_option("--seeds", args->seeds, "seeds, e.g. --seeds 3 4 5")
      ->capture_default_str()
      ->expected(1, 1000);
  not_a_file(*cmd, cmd->add_option("--robots", args->robots, "test beds: ur5, lwr4")
                       ->capture_default_str()
                       ->check(CLI::IsMember({"ur5", "lwr4"}))
                       ->expected(1, 2));
  cmd->add_option("--seconds-per-move", o.seconds_per_move, "robot time per location visited, s")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seconds-per-reading", o.seconds_per_reading,
                  "robot time per tracker reading, s")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--batch", o.batch_size, "locations per adaptive batch")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--budget", o.budget,
                  "most fiducials of the adaptive loop (0: a quarter of Procedure 1's at d_min)")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000));
  cmd->add_option("--goal-sd-mm", args->goal_sd_mm,
                  "the loop's goal, predicted RMS_T at the targets, mm (default: 1.1 x the RMS_T "
                  "of Procedure 1 at the smallest cube edge in the same cell)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--min-gain", o.min_relative_gain,
                  "also stop when a batch is expected to lower the predicted RMS_T by less than "
                  "this fraction (plan-next's rule is 0.01; 0: goal and budget only)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.99));
  not_a_file(*cmd, cmd->add_option("--interpolation", args->interpolation,
                                   "what the loop and the grid correct with (the loop's measured "
                                   "and predicted RMS_T, its goal and stop): joint, kriging, rbf, "
                                   "trilinear, auto")
                       ->capture_default_str()
                       ->check(CLI::IsMember({"joint", "kriging", "rbf", "trilinear", "auto"})));
  cmd->add_option("--candidate-spacing-mm", args->candidate_spacing_mm,
                  "adaptive candidate lattice spacing, mm")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--cube-edges-mm", args->cube_edges_mm,
                  "Procedure 1's octuplet cube edges a, mm (default dataset B's 50 45 ... 5)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--quick", args->quick,
                "Procedure 1 at a = 50 and 5 mm only, no grid, batches of 60, RMS_T measured "
                "at STOP only (for tests)")
      ->excludes("--cube-edges-mm")
      ->excludes("--batch");
  cmd->add_flag("--json", args->json, "print one JSON object instead of the table");
  add_output_option(*cmd, "--report", args->report,
                    "write an HTML page with the table and the RMS_T-against-fiducials plot");
  cmd->callback([args] {
    try {
      run_adaptive_study(*args);
    } catch (const InputError& e) {
      const std::string what = e.what();
      throw InputError(what.starts_with("adaptive study") ? what : "adaptive study: " + what);
    }
  });
}

}  // namespace

VRREG_REGISTER_COMMAND(97, add_adaptive_study_command);

}  // namespace vrreg::cli
