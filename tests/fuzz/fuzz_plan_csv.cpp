// SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the plan CSV reader; an accepted plan must write and read back.
#include <sstream>

#include "fuzz_support.hpp"
#include "vrreg/io/plan_csv.hpp"

namespace vrreg::fuzz {

int plan_csv(const std::uint8_t* data, std::size_t size) {
  io::PlanFile plan;
  if (!reads_or_refuses("plan CSV", [&] {
        std::istringstream in(as_text(data, size));
        plan = io::parse_plan_csv(in, "fuzz-plan.csv");
      })) {
    return 0;
  }
  for (const io::PlanRow& row : plan.rows) {
    require(row.robot_m.allFinite(), "plan CSV: accepted a non-finite position");
  }
  std::string written;
  try {
    written = io::format_plan_csv(plan.rows, plan.comments);
  } catch (const std::exception& e) {
    throw Finding(std::string("plan CSV: an accepted plan cannot be written: ") + e.what());
  }
  io::PlanFile again;
  require(reads_or_refuses("plan CSV (written back)",
                           [&] {
                             std::istringstream in(written);
                             again = io::parse_plan_csv(in, "written.csv");
                           }),
          "plan CSV: the written plan does not read back");
  require(again.rows.size() == plan.rows.size(), "plan CSV: rows lost writing back");
  return 0;
}

}  // namespace vrreg::fuzz

VRREG_FUZZ_ENTRY(vrreg::fuzz::plan_csv)
