#include "strategy_cli.hpp"

#include <cstdio>

#include "vrreg/core/check.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/kinematics/configuration_order.hpp"
#include "vrreg/planning/strategy3_correction.hpp"
#include "vrreg/planning/strategy3_registration.hpp"

namespace vrreg::cli {

const char* const kStrategyHelp =
    "Arm configurations (Procedure 2, paper section 4.4), for files with a config column and\n"
    "joint columns q1_rad..qN_rad:\n"
    "  --strategy 1  labels as the file lists them (the IK's order); one registration per\n"
    "                label: give --config N.\n"
    "  --strategy 2  labels re-assigned along the visiting path (the order in which points first\n"
    "                appear in the file): at each point label 1 is the configuration nearest the\n"
    "                previous point's label 1, labels 2..m follow by joint distance to it; give\n"
    "                --config N. The model stores the new labels; evaluate relabels the targets'\n"
    "                file the same way, so keep fiducials and targets in one file (one path).\n"
    "  --strategy 3  one registration from the fiducials at the 8 corners of the whole volume,\n"
    "                each in a random configuration (register --seed, printed); each target is\n"
    "                corrected from the 8 fiducials of the cube around it (--cube-mm), each taken\n"
    "                in the configuration whose joints are nearest the target's. The model keeps\n"
    "                every configuration; evaluate --config N picks the targets measured in N.\n"
    "  --joint-norm  l2 (the paper's, default) or linf; angles are wrapped to (-pi, pi].\n";

void StrategyFlags::add_to(CLI::App& command, bool for_register) {
  command
      .add_option("--strategy", strategy,
                  for_register ? "Procedure 2 strategy 1, 2 or 3 (see below)"
                               : "Procedure 2 strategy (default: the model's; see below)")
      ->check(CLI::Range(1, 3));
  command
      .add_option("--joint-norm", joint_norm,
                  for_register ? "joint-space distance of strategies 2 and 3: l2 (default) or linf"
                               : "strategy 3: joint-space distance (default: the model's)")
      ->check(CLI::IsMember({"l2", "linf"}));
  if (for_register) {
    command.add_option("--seed", seed,
                       "strategy 3: seed of the random corner configurations (default 1)");
  }
  command.footer(kStrategyHelp);
}

void require_configurations(const MeasurementSet& set, int strategy) {
  if (!set.has_config) {
    throw io::FileError(set.source, 0,
                        "--strategy " + std::to_string(strategy) +
                            " needs a config column (the arm configuration of each row)");
  }
  if (set.n_joints == 0) {
    throw io::FileError(set.source, 0,
                        "--strategy " + std::to_string(strategy) +
                            " needs joint columns (q1_rad..qN_rad or q1_deg..qN_deg)");
  }
}

int register_strategy(const StrategyFlags& flags, const std::optional<int>& config, bool robust) {
  const int s = flags.strategy.value_or(0);
  VRREG_THROW_UNLESS((s != 1 && s != 2) || config,
                     "--strategy " << s << " registers one configuration: give --config N");
  VRREG_THROW_UNLESS(s != 3 || !config,
                     "--strategy 3 registers every configuration at once; "
                     "--config N selects targets in evaluate");
  VRREG_THROW_UNLESS(s != 3 || !robust, "--robust is not available with --strategy 3");
  VRREG_THROW_UNLESS(s == 3 || !flags.seed, "--seed is for --strategy 3");
  VRREG_THROW_UNLESS(s >= 2 || flags.joint_norm.empty(), "--joint-norm is for --strategy 2 or 3");
  return s;
}

int evaluate_strategy(const StrategyFlags& flags, const RegistrationModel& model,
                      const std::string& model_path) {
  const int built = model.procedure2.strategy;
  const int s = flags.strategy.value_or(built);
  if (s != built && !(s == 1 && built == 0)) {
    throw io::FileError(
        model_path, 0,
        "the model was built with " +
            (built == 0 ? std::string("no strategy") : "--strategy " + std::to_string(built)) +
            ", not --strategy " + std::to_string(s) + ": register again with it");
  }
  VRREG_THROW_UNLESS(s >= 2 || flags.joint_norm.empty(), "--joint-norm is for strategies 2 and 3");
  if (s == 2 && !flags.joint_norm.empty() && flags.joint_norm != model.procedure2.joint_norm) {
    throw io::FileError(model_path, 0,
                        "the model's Strategy 2 labels use --joint-norm " +
                            model.procedure2.joint_norm + "; the targets must use the same");
  }
  return s;
}

kinematics::JointNorm joint_norm(const StrategyFlags& flags, const RegistrationModel* model) {
  if (!flags.joint_norm.empty()) return kinematics::parse_joint_norm(flags.joint_norm);
  if (model != nullptr) return kinematics::parse_joint_norm(model->procedure2.joint_norm);
  return kinematics::JointNorm::kL2;
}

planning::Strategy2Result relabel_file(const MeasurementSet& set, kinematics::JointNorm norm) {
  require_configurations(set, 2);
  try {
    return planning::relabel_strategy2(set, norm);
  } catch (const io::FileError&) {
    throw;
  } catch (const InputError& e) {
    throw io::FileError(set.source, 0, e.what());
  }
}

Strategy3Model build_strategy3_model(const MeasurementSet& set, std::uint64_t seed,
                                     kinematics::JointNorm norm,
                                     const RegistrationOptions& registration,
                                     const InterpolationSettings& interpolation) {
  require_configurations(set, 3);
  Strategy3Model out;
  RegistrationModel& model = out.model;
  for (const std::size_t i : set.select(Role::kFiducial))
    model.fiducials.push_back(set.locations[i]);
  planning::Strategy3Options options;
  options.seed = seed;
  options.match_tolerance_m = interpolation.match_tolerance_m;
  options.registration = registration;
  planning::Strategy3Registration r;
  try {
    r = planning::register_volume_corners(model.fiducials, options);
  } catch (const InputError& e) {
    throw io::FileError(set.source, 0, e.what());
  }
  out.registration = r.registration;
  out.registered_sensor_m.resize(3, 8);
  out.registered_robot_m.resize(3, 8);
  for (std::size_t c = 0; c < 8; ++c) {
    const Location& f = model.fiducials[r.corner_fiducials[c]];
    out.registered_sensor_m.col(static_cast<Eigen::Index>(c)) = f.sensor_m;
    out.registered_robot_m.col(static_cast<Eigen::Index>(c)) = f.robot_m;
    model.procedure2.registration_fiducials.push_back(r.corner_fiducials[c]);
  }
  model.T_robot_sensor = r.registration.T_robot_sensor;
  model.fre_m = r.registration.fre_m;
  model.corrections_sensor_m = r.corrections_sensor_m;
  model.interpolation = interpolation;
  model.source = set.source;
  model.procedure2.strategy = 3;
  model.procedure2.joint_norm = kinematics::to_string(norm);
  model.procedure2.seed = seed;
  return out;
}

TargetCorrection correct_strategy3(const RegistrationModel& model, const MeasurementSet& set,
                                   const std::vector<std::size_t>& rows,
                                   const InterpolationSettings& settings,
                                   kinematics::JointNorm norm) {
  require_configurations(set, 3);
  if (settings.method != InterpolationMethod::kOctuplet &&
      settings.method != InterpolationMethod::kAuto) {
    throw io::FileError(set.source, 0,
                        std::string("--strategy 3 corrects with octuplets, not --interpolation ") +
                            to_string(settings.method));
  }
  planning::Strategy3CorrectionOptions options;
  options.cube_edge_m = settings.cube_edge_m;
  options.match_tolerance_m = settings.match_tolerance_m;
  options.norm = norm;
  std::vector<Location> targets;
  targets.reserve(rows.size());
  for (const std::size_t i : rows) targets.push_back(set.locations[i]);
  try {
    return planning::correct_targets_strategy3(model, targets, options);
  } catch (const InputError& e) {
    throw io::FileError(set.source, 0, e.what());
  }
}

void add_strategy_json(nlohmann::json& j, const RegistrationModel& model,
                       const std::optional<planning::Strategy2Summary>& relabelled) {
  const ConfigurationStrategy& p = model.procedure2;
  j["strategy"] = p.strategy == 0 ? nlohmann::json(nullptr) : nlohmann::json(p.strategy);
  if (p.strategy >= 2) j["joint_norm"] = p.joint_norm;
  if (relabelled) {
    // switched_fraction is the paper's figure (section 5.2: "14 % of nominal locations"): the
    // share of nominal points with any configuration relabelled.
    j["switched_fraction"] = relabelled->switched_points_fraction();
    j["switched_points_fraction"] = relabelled->switched_points_fraction();
    j["n_switched_points"] = relabelled->n_switched_points;
    j["n_points"] = relabelled->n_points;
    j["switched_locations_fraction"] = relabelled->switched_locations_fraction();
    j["n_switched_locations"] = relabelled->n_switched;
    j["n_locations"] = relabelled->n_locations;
  }
  if (p.strategy == 3) {
    j["seed"] = p.seed ? nlohmann::json(*p.seed) : nlohmann::json(nullptr);
    std::vector<std::string> names;
    for (const std::size_t f : p.registration_fiducials) {
      names.push_back(location_name(model.fiducials[f]));
    }
    j["registration_fiducials"] = names;
    j["n_correction_fiducials"] = model.fiducials.size();
  }
}

void print_strategy(const RegistrationModel& model,
                    const std::optional<planning::Strategy2Summary>& relabelled) {
  const ConfigurationStrategy& p = model.procedure2;
  if (p.strategy == 1) {
    std::printf("  strategy 1                    configuration labels as listed in the file\n");
  } else if (p.strategy == 2) {
    std::printf("  strategy 2                    labels along the visiting path (%s)",
                p.joint_norm.c_str());
    if (relabelled) {
      std::printf(": %d of %d points (%.1f %%) and %d of %d locations (%.1f %%) switched",
                  relabelled->n_switched_points, relabelled->n_points,
                  100.0 * relabelled->switched_points_fraction(), relabelled->n_switched,
                  relabelled->n_locations, 100.0 * relabelled->switched_locations_fraction());
      const char* sep = " (file label";
      for (const auto& [label, n] : relabelled->switched_by_file_label) {
        std::printf("%s %d: %d", sep, label, n);
        sep = ",";
      }
      if (!relabelled->switched_by_file_label.empty()) std::printf(")");
    }
    std::printf("\n");
  } else if (p.strategy == 3) {
    std::printf(
        "  strategy 3                    one registration from the volume corners, seed %llu:\n",
        static_cast<unsigned long long>(p.seed.value_or(0)));
    std::printf("                               ");
    for (const std::size_t f : p.registration_fiducials) {
      std::printf(" %s", location_name(model.fiducials[f]).c_str());
    }
    std::printf(
        "\n  corrections for               %zu fiducials in every configuration "
        "(nearest to each target's by %s)\n",
        model.fiducials.size(), p.joint_norm.c_str());
  }
}

std::string location_name(const Location& location) {
  return location.point +
         (location.config ? " (config " + std::to_string(*location.config) + ")" : "");
}

}  // namespace vrreg::cli
