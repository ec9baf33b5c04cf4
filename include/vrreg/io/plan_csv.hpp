// SPDX-License-Identifier: Apache-2.0
#pragma once
// Plan file of Procedure 1 (paper section 6; written by `vrreg plan`, to be measured by a robot
// program or `vrreg simulate --plan`): the locations to visit, one row each, in visiting order.
//
// Columns: point, role, part, robot_x_mm, robot_y_mm, robot_z_mm, config, q1_rad..qN_rad. point,
// role, robot_* and config/q* mean what they mean in a measurement CSV (design.md 6), so adding
// sensor_* columns (and dropping `part`) makes a measurement file; `part` names the part point
// whose cube the row belongs to. `#` comment lines (written first) hold the planning parameters.
// The reader takes the columns in any order (case-insensitive, _m / _deg allowed); part, config
// and joints are optional; (point, config) must be unique; bad input throws FileError.
// A row of role `via` is a joint-space via point the robot moves to, never measures (one approach
// direction per joint, planning/approach.hpp): it comes just before the row of the location it
// leads to, with that row's point label; the reader attaches it to that row (PlanRow::via).
#include <Eigen/Core>
#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"

namespace vrreg::io {

/// A via point moved to just before a location, never measured (written as its own `via` row).
struct PlanVia {
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();  ///< nominal TCP, robot base frame [m]
  std::vector<double> q_rad{};                        ///< commanded joints [rad]
};

/// One location of a plan, SI units.
struct PlanRow {
  std::string point{};  ///< label: not empty, no comma, quote, newline, leading '#' or spaces
  Role role = Role::kFiducial;
  std::string part{};  ///< part point of its cube (same label rules; empty when not given)
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();  ///< TCP position, robot base frame [m]
  std::optional<int> config{};  ///< configuration label index (all rows or none)
  std::vector<double> q_rad{};  ///< commanded joints [rad] (same count in every row)
  std::size_t line = 0;       ///< 1-based line when read from a file
  std::optional<PlanVia> via{};  ///< the via point moved to just before (approach directions)
};

/// A plan file's rows (visiting order) and comment lines (without the leading "# ").
struct PlanFile {
  std::vector<PlanRow> rows{};
  std::vector<std::string> comments{};
  int n_joints = 0;
  bool has_config = false;
};

/// The CSV text: `comments` as "# " lines, the header, one row per location (mm, rad, numbers
/// that read back exactly). Throws InputError on rows that cannot be written consistently.
std::string format_plan_csv(const std::vector<PlanRow>& rows,
                            const std::vector<std::string>& comments = {});

/// Writes format_plan_csv(rows, comments) to `path` atomically (whole or not at all).
void write_plan_csv(const std::string& path, const std::vector<PlanRow>& rows,
                    const std::vector<std::string>& comments = {});

/// Reads the plan file at `path`; throws FileError ("path:line: message") on bad input.
PlanFile read_plan_csv(const std::string& path);

/// Reads a plan file from a stream; `source_name` names it in errors.
PlanFile parse_plan_csv(std::istream& in, const std::string& source_name);

}  // namespace vrreg::io
