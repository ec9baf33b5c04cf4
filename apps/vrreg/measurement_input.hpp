// SPDX-License-Identifier: Apache-2.0
#pragma once
// Measurement files as the commands read them: the io reader, plus a plausibility check of the
// coordinates' extent that the command line reports (the library never prints).
#include <string>

#include "vrreg/core/measurement.hpp"
#include "vrreg/io/measurement_csv.hpp"

namespace vrreg::cli {

/// A robot cell spans a few metres; positions spread over more than this are almost surely
/// millimetres written in `_m` columns (a 250 mm volume read as 250 m) [m].
inline constexpr double kMaxPlausibleSpanM = 20.0;

/// The warning for `set` (its file, the span in metres and the likely cause), or "" when the robot
/// and sensor positions each span at most kMaxPlausibleSpanM along every axis.
std::string implausible_extent_warning(const MeasurementSet& set);

/// io::read_measurement_csv, then the warning above on stderr ("vrreg: warning: ...") if any.
MeasurementSet read_measurements(const std::string& path, const io::CsvReadOptions& options = {});

}  // namespace vrreg::cli
