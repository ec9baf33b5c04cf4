// SPDX-License-Identifier: Apache-2.0
#include "plan_program_cli.hpp"

#include <cstdio>

#include "cli_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/planning/monitor_points.hpp"
#include "vrreg/planning/robot_program.hpp"

namespace vrreg::cli {

void add_program_options(CLI::App& command, PlanArgs& args) {
  CLI::Option* format =
      command
          .add_option("--export", args.export_format,
                      "also write the plan as a robot program: urscript (UR movej list), krl "
                      "(KUKA PTP list) or csv (joints); a pause for the tracker readings at each "
                      "location (docs/hand-eye.md)")
          ->check(CLI::IsMember({"urscript", "krl", "csv"}));
  not_a_file(command, format);
  add_output_option(command, "--program", args.program, "with --export: the program file")
      ->needs(format);
  format->needs("--program");
  add_output_option(command, "--monitor-program", args.monitor_program,
                    "with --export and --monitor: the program a check runs (the monitor points "
                    "only, in --monitor-visits rounds)")
      ->needs(format);
  command
      .add_option("--repeats", args.repeats,
                  "with --export: tracker readings per location the program asks for "
                  "(default: 12, the paper's K)")
      ->needs(format)
      ->check(CLI::Range(1, 1000));
}

std::string plan_program(const PlanArgs& args, const planning::PlanResult& plan,
                         bool monitors_only) {
  std::vector<planning::ProgramLocation> locations;
  if (!monitors_only) {
    for (const planning::PlannedLocation& l : plan.locations) {
      if (l.role != Role::kMonitor)
        locations.push_back({l.point, l.role, l.config.to_string(), l.q_rad, -1, l.via_q_rad});
    }
  }
  // Monitor points last, in rounds: at registration as at every check.
  for (planning::ProgramLocation& l :
       planning::monitor_program_locations(plan, args.monitor_visits))
    locations.push_back(std::move(l));
  VRREG_THROW_UNLESS(!locations.empty(), "no monitor points to write a program for");
  planning::ProgramOptions options;
  if (args.repeats > 0) options.repeats = args.repeats;
  return planning::robot_program(locations, planning::parse_program_format(args.export_format),
                                 options);
}

}  // namespace vrreg::cli
