// SPDX-License-Identifier: Apache-2.0
#pragma once
// Procedure 2 (paper section 4.4) on the command line: the --strategy, --joint-norm and --seed
// flags of register and evaluate, and how the strategy is printed.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/pipeline/evaluate.hpp"
#include "vrreg/pipeline/model.hpp"
#include "vrreg/planning/procedure2.hpp"
#include "vrreg/planning/strategy2_labels.hpp"

namespace vrreg::cli {

/// The Procedure 2 flags.
struct StrategyFlags {
  std::optional<int> strategy;        ///< absent: today's behaviour (register) / the model's
  std::string joint_norm;             ///< empty: l2 (register) / the model's (evaluate)
  std::optional<std::uint64_t> seed;  ///< register --strategy 3 only; default 1
  /// Adds --strategy, --joint-norm and (for register) --seed to `command`.
  void add_to(CLI::App& command, bool for_register);
};

/// Register's Procedure 2 options from the flags (flag combinations that only make sense on the
/// command line are checked here; the library checks the rest).
planning::Procedure2 register_procedure2(const StrategyFlags& flags);

/// Evaluate's strategy and joint-norm options from the flags (unset: the model's).
void apply_evaluate_flags(const StrategyFlags& flags, EvaluateOptions& options);

/// Prints Procedure 2 as an indented table line (nothing without a strategy).
void print_strategy(const RegistrationModel& model,
                    const std::optional<planning::Strategy2Summary>& relabelled);

/// The --help text on strategies shared by register and evaluate.
extern const char* const kStrategyHelp;

}  // namespace vrreg::cli
