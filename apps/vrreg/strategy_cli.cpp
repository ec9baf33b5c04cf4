// SPDX-License-Identifier: Apache-2.0
#include "strategy_cli.hpp"

#include <cstdio>

#include "cli_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/io/result_json.hpp"
#include "vrreg/kinematics/configuration_order.hpp"

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
  not_a_file(
      command,
      command
          .add_option("--joint-norm", joint_norm,
                      for_register
                          ? "joint-space distance of strategies 2 and 3: l2 (default) or linf"
                          : "strategy 3: joint-space distance (default: the model's)")
          ->check(CLI::IsMember({"l2", "linf"})));
  if (for_register) {
    add_seed_option(command, "--seed", seed,
                    "strategy 3: seed of the random corner configurations (default 1)");
  }
  command.footer(kStrategyHelp);
}

planning::Procedure2 register_procedure2(const StrategyFlags& flags) {
  planning::Procedure2 p;
  p.strategy = planning::strategy_from_number(flags.strategy.value_or(0));
  VRREG_THROW_UNLESS(flags.strategy.value_or(0) >= 2 || flags.joint_norm.empty(),
                     "--joint-norm is for --strategy 2 or 3");
  if (!flags.joint_norm.empty()) p.joint_norm = kinematics::parse_joint_norm(flags.joint_norm);
  p.seed = flags.seed;
  return p;
}

void apply_evaluate_flags(const StrategyFlags& flags, EvaluateOptions& options) {
  if (flags.strategy) options.strategy = planning::strategy_from_number(*flags.strategy);
  if (!flags.joint_norm.empty())
    options.joint_norm = kinematics::parse_joint_norm(flags.joint_norm);
}

void print_strategy(const RegistrationModel& model,
                    const std::optional<planning::Strategy2Summary>& relabelled) {
  const planning::Procedure2& p = model.procedure2;
  const int strategy = planning::strategy_number(p.strategy);
  if (strategy == 1) {
    std::printf("  strategy 1                    configuration labels as listed in the file\n");
  } else if (strategy == 2) {
    std::printf("  strategy 2                    labels along the visiting path (%s)",
                kinematics::to_string(p.joint_norm));
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
  } else if (strategy == 3) {
    std::printf(
        "  strategy 3                    one registration from the volume corners, seed %llu:\n",
        static_cast<unsigned long long>(p.seed.value_or(0)));
    std::printf("                               ");
    for (const std::size_t f : p.registration_fiducials) {
      std::printf(" %s", io::location_name(model.fiducials[f]).c_str());
    }
    std::printf(
        "\n  corrections for               %zu fiducials in every configuration "
        "(nearest to each target's by %s)\n",
        model.fiducials.size(), kinematics::to_string(p.joint_norm));
  }
}

}  // namespace vrreg::cli
