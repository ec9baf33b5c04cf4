// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reads the part points of Procedure 1 (paper section 6, Fig. 16; `vrreg plan --parts`).
//
// Parts file: a CSV with a header line and one row per part point, e.g.
//   # the four features of the housing, nominal positions in the UR5 base frame
//   point,robot_x_mm,robot_y_mm,robot_z_mm
//   hole_A,450,-100,250
// Columns (any order, case-insensitive): point (the part point's label) and robot_x/y/z in _mm
// or _m (the same for all three), the nominal position in the robot base frame. A measurement CSV
// (design.md 6) is accepted as well: with a `role` column only `target` rows are part points
// (`fiducial` rows are skipped), and its sensor_*, config, repeat and q* columns are ignored; rows
// repeating a point label (repeat readings, configurations) must give the same position and count
// once. `#` lines are comments; blank lines, CRLF, a UTF-8 BOM and a missing final newline are
// fine; quoted fields, a label with a quote or a leading '#' (a plan file cannot hold it),
// unknown columns, short or long rows, non-finite numbers, a point label used at two positions, or
// no part point at all throw FileError naming the file and line.
#include <Eigen/Core>
#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace vrreg::io {

/// One part point as read: label and nominal robot-frame position [m].
struct PartRecord {
  std::string point{};
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();
  std::size_t line = 0;  ///< 1-based line of its first row
};

/// Reads the parts file at `path`, in file order; throws FileError on bad input.
std::vector<PartRecord> read_parts_csv(const std::string& path);

/// Reads a parts file from a stream; `source_name` names it in errors.
std::vector<PartRecord> parse_parts_csv(std::istream& in, const std::string& source_name);

}  // namespace vrreg::io
