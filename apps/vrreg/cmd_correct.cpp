// vrreg correct: RRBC-corrected robot-frame positions for points measured by the sensor
// (Eq. 7, 8, then mapped with {R, tau}): what the robot should be commanded to.
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

namespace vrreg::cli {
namespace {

struct CorrectArgs {
  std::string model;
  std::string points;
  std::optional<int> config;
  InterpolationFlags interpolation;
  std::string output;
  bool json = false;
};

void run_correct(const CorrectArgs& args) {
  const RegistrationModel model = io::read_model_json(args.model);
  io::CsvReadOptions read_options;
  read_options.require_robot = false;  // points to correct need only their sensor position
  MeasurementSet set = io::read_measurement_csv(args.points, read_options);
  const int strategy = model.procedure2.strategy;  // Procedure 2 (section 4.4): as registered
  if (strategy == 2) set = relabel_file(set, joint_norm({}, &model)).set;
  const std::optional<int> config = args.config ? args.config : model.config;
  const std::vector<std::size_t> rows = select_rows(set, Role::kTarget, config);
  const InterpolationSettings settings = args.interpolation.apply(model.interpolation);
  Points3 nominal(3, 0);
  if (settings.method == InterpolationMethod::kOctuplet || strategy == 3) {
    for (std::size_t i : rows) {
      VRREG_THROW_UNLESS(set.locations[i].has_robot,
                         args.points << ":" << set.locations[i].source_line
                                     << ": octuplet interpolation needs the nominal robot position "
                                        "of every point (robot_x_mm, ...)");
    }
    nominal = set.robot_points(rows);
  }
  const TargetCorrection c =
      strategy == 3 ? correct_strategy3(model, set, rows, settings, joint_norm({}, &model))
                    : correct_targets(model, set.sensor_points(rows), nominal, settings,
                                      source_lines(set, rows));

  std::ostringstream out;
  out.precision(12);
  out << "# vrreg correct: model " << args.model << ", points " << args.points
      << ", interpolation " << to_string(c.method_used) << " (" << c.layout << ")\n";
  out << "point,config,status,robot_x_mm,robot_y_mm,robot_z_mm,"
         "uncorrected_robot_x_mm,uncorrected_robot_y_mm,uncorrected_robot_z_mm,"
         "correction_x_mm,correction_y_mm,correction_z_mm\n";
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Location& loc = set.locations[rows[k]];
    const auto n = static_cast<Eigen::Index>(k);
    out << loc.point << ',' << (loc.config ? std::to_string(*loc.config) : "") << ','
        << to_string(c.stencils[k].status);
    for (int a = 0; a < 3; ++a) out << ',' << units::m_to_mm(c.corrected_robot_m(a, n));
    for (int a = 0; a < 3; ++a) out << ',' << units::m_to_mm(c.uncorrected_robot_m(a, n));
    for (int a = 0; a < 3; ++a) out << ',' << units::m_to_mm(c.corrections_sensor_m(a, n));
    out << '\n';
  }
  io::write_file_atomically(args.output, out.str());

  if (args.json) {
    nlohmann::json j;
    j["points"] = rows.size();
    j["n_flagged"] = c.n_flagged;
    j["interpolation"] = to_string(c.method_used);
    j["layout"] = c.layout;
    j["output"] = args.output;
    print_json(j);
    return;
  }
  std::printf("corrected %zu points from %s with model %s\n", rows.size(), args.points.c_str(),
              args.model.c_str());
  std::printf("  interpolation                 %s: %s\n", to_string(c.method_used), c.layout.c_str());
  if (c.n_flagged > 0) {
    std::printf("  not correctable               %d points (outside the fiducials; status column "
                "says why; robot_* holds the uncorrected mapping)\n",
                c.n_flagged);
  }
  std::printf("  robot-frame positions (mm) written to %s\n", args.output.c_str());
}

void add_correct_command(CLI::App& app) {
  auto args = std::make_shared<CorrectArgs>();
  CLI::App* cmd = app.add_subcommand(
      "correct", "RRBC-correct points measured by the sensor and map them to the robot frame "
                 "(paper Eq. 7, 8)");
  cmd->add_option("--model", args->model, "model JSON written by 'vrreg register -o'")->required();
  cmd->add_option("--points", args->points,
                  "measurement CSV; its target rows are corrected (robot columns optional)")
      ->required();
  cmd->add_option("--config", args->config, "use only rows with this configuration label");
  args->interpolation.add_to(*cmd);
  cmd->add_option("-o,--output", args->output, "write corrected positions (CSV, mm) here")
      ->required();
  cmd->add_flag("--json", args->json, "print a JSON summary instead of the table");
  cmd->callback([args] { run_correct(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(30, add_correct_command);

}  // namespace vrreg::cli
