#pragma once
// Small helpers shared by the commands: millimetre formatting, option parsing glue.
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "vrreg/core/measurement.hpp"
#include "vrreg/core/model.hpp"

namespace vrreg::cli {

/// "0.626" style: a length in metres printed in mm with `decimals` places.
std::string mm(double metres, int decimals = 3);
/// "[x, y, z]" in mm.
std::string mm3(const Eigen::Vector3d& metres, int decimals = 3);
/// A JSON array of a 3-vector in mm.
nlohmann::json json_mm3(const Eigen::Vector3d& metres);

/// Command-line interpolation options, applied over a model's stored settings.
struct InterpolationFlags {
  std::string method;          ///< empty: keep the model's
  std::optional<double> cube_mm;
  void add_to(CLI::App& command);
  [[nodiscard]] InterpolationSettings apply(InterpolationSettings stored) const;
};

/// Indices of rows with `role` (and `config` when given); throws naming the file when none.
std::vector<std::size_t> select_rows(const MeasurementSet& set, Role role,
                                     std::optional<int> config);

/// The file line of each selected row (its place in the visiting order).
std::vector<std::size_t> source_lines(const MeasurementSet& set,
                                      const std::vector<std::size_t>& rows);

/// Prints JSON to stdout, two-space indented, with a final newline.
void print_json(const nlohmann::json& j);

}  // namespace vrreg::cli
