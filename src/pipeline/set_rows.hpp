// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to pipeline: selecting rows of a measurement set, with errors that name its source.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"

namespace vrreg::pipeline_detail {

/// Throws FileError(set.source, line, message), or InputError(message) for a set without a source
/// (arrays given in memory).
[[noreturn]] void fail(const MeasurementSet& set, const std::string& message, std::size_t line = 0);

/// Indices of rows with `role` (and `config` when given); throws naming the source when none.
std::vector<std::size_t> select_rows(const MeasurementSet& set, Role role,
                                     std::optional<int> config);

/// The file line of each selected row (its place in the visiting order).
std::vector<std::size_t> source_lines(const MeasurementSet& set,
                                      const std::vector<std::size_t>& rows);

/// The point labels and configuration labels of the selected rows, appended to `names`, `configs`.
void labels_of(const MeasurementSet& set, const std::vector<std::size_t>& rows,
               std::vector<std::string>& names, std::vector<std::optional<int>>& configs);

/// The joint angles of the selected rows, one column per row, or 0 x 0 when a row has none.
Eigen::MatrixXd joints_of(const MeasurementSet& set, const std::vector<std::size_t>& rows);

/// The selected locations' approach directions (Location::approach_sign), one column each, or
/// 0 x 0 when some location has none.
Eigen::MatrixXd approach_of(const MeasurementSet& set, const std::vector<std::size_t>& rows);

/// The selected locations, copied.
std::vector<Location> locations_of(const MeasurementSet& set, const std::vector<std::size_t>& rows);

}  // namespace vrreg::pipeline_detail
