#pragma once
// Procedure 2 (paper section 4.4) on the command line: the --strategy, --joint-norm and --seed
// flags of register and evaluate, and the glue from files to the planning library.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/core/model.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/planning/strategy2_labels.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg::cli {

/// The Procedure 2 flags.
struct StrategyFlags {
  std::optional<int> strategy;        ///< absent: today's behaviour (register) / the model's
  std::string joint_norm;             ///< empty: l2 (register) / the model's (evaluate)
  std::optional<std::uint64_t> seed;  ///< register --strategy 3 only; default 1
  /// Adds --strategy, --joint-norm and (for register) --seed to `command`.
  void add_to(CLI::App& command, bool for_register);
};

/// What register --strategy 3 builds: the model and its registration from the volume corners.
struct Strategy3Model {
  RegistrationModel model;  ///< all fiducials in all configurations, epsilon vs one {R, tau}
  RegistrationResult registration;  ///< from the 8 volume-corner fiducials
  Points3 registered_sensor_m;      ///< those 8 fiducials, sensor frame [m]
  Points3 registered_robot_m;       ///< and robot frame [m]
};

/// Throws InputError naming `set.source` unless it has a config column and joint columns.
void require_configurations(const MeasurementSet& set, int strategy);

/// Checks register's flag combination; returns the strategy (0 when not given).
int register_strategy(const StrategyFlags& flags, const std::optional<int>& config, bool robust);
/// Checks evaluate's flags against the model (built with strategy s); returns the strategy used.
int evaluate_strategy(const StrategyFlags& flags, const RegistrationModel& model,
                      const std::string& model_path);
/// The joint norm: the flag, else the model's (evaluate), else l2.
kinematics::JointNorm joint_norm(const StrategyFlags& flags, const RegistrationModel* model);

/// Strategy 2 labels for the whole file; errors name the file.
planning::Strategy2Result relabel_file(const MeasurementSet& set, kinematics::JointNorm norm);

/// Strategy 3 model from every fiducial of `set` (errors name the file).
Strategy3Model build_strategy3_model(const MeasurementSet& set, std::uint64_t seed,
                                     kinematics::JointNorm norm,
                                     const RegistrationOptions& registration,
                                     const InterpolationSettings& interpolation);

/// Strategy 3 correction of the target `rows` of `set` (errors name the file).
TargetCorrection correct_strategy3(const RegistrationModel& model, const MeasurementSet& set,
                                   const std::vector<std::size_t>& rows,
                                   const InterpolationSettings& settings,
                                   kinematics::JointNorm norm);

/// Adds "strategy" (null without one) and, per strategy, "joint_norm", "switched_fraction" (=
/// "switched_points_fraction", the paper's), "switched_locations_fraction" and their counts (2:
/// from `relabelled`), "seed", "registration_fiducials" (3) to `j`.
void add_strategy_json(nlohmann::json& j, const RegistrationModel& model,
                       const std::optional<planning::Strategy2Summary>& relabelled);
/// Prints the same as an indented table line (nothing without a strategy).
void print_strategy(const RegistrationModel& model,
                    const std::optional<planning::Strategy2Summary>& relabelled);

/// "F1 (config 2)": a location's point and label, for messages.
std::string location_name(const Location& location);

/// The --help text on strategies shared by register and evaluate.
extern const char* const kStrategyHelp;

}  // namespace vrreg::cli
