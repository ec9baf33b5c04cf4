// SPDX-License-Identifier: Apache-2.0
#pragma once
// `vrreg plan --export urscript|krl|csv --program FILE`: the plan as a robot program.
#include <CLI/CLI.hpp>

#include "plan_output.hpp"

namespace vrreg::cli {

/// Adds --export, --program and --repeats.
void add_program_options(CLI::App& command, PlanArgs& args);

/// The program of `plan` (visiting order) in the format of --export, for args.program.
/// The plan as a robot program (monitor points last, in rounds); `monitors_only`: the check's
/// program, the monitor points alone.
std::string plan_program(const PlanArgs& args, const planning::PlanResult& plan,
                         bool monitors_only = false);

}  // namespace vrreg::cli
