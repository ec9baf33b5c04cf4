// SPDX-License-Identifier: Apache-2.0
#pragma once
// A reproduction as a flat list of named numbers ("cells"), each named by its JSON pointer in
// `vrreg reproduce --json` (e.g. "/table1/A1/cor_rms_t_mm", "/table2/3/gamma_percent"), so that
// one seed and the mean +- sd of many seeds are printed, written and compared the same way.
// Lengths in mm and gamma in percent here, as the paper prints them.
#include <string>
#include <string_view>
#include <vector>

#include "vrreg/experiments/reproduction.hpp"

namespace vrreg::experiments {

/// What a cell holds.
enum class CellKind {
  kValue,  ///< a measured number (mean +- sd over seeds)
  kCount,  ///< an integer count (its mean over seeds may not be)
  kKey,    ///< identifies a row (config, strategy, d): the same on every seed
};

/// One named number; NaN means "not defined" (null in JSON, "-" in tables).
struct Cell {
  std::string pointer{};
  CellKind kind = CellKind::kValue;
  double value = 0.0;
};

/// The cells of Table 1, dataset B (Figures 7, 8), the KUKA summary and Table 2, in a fixed order.
std::vector<Cell> reproduction_cells(const Reproduction& r);

/// A cell over seeds.
struct CellSummary {
  std::string pointer{};
  CellKind kind = CellKind::kValue;
  double mean = 0.0;    ///< NaN when undefined on some seed
  double sd = 0.0;      ///< sample sd over seeds (0 for one seed)
  double median = 0.0;  ///< median over seeds (mean of the middle two for an even count)
  int n = 0;            ///< seeds
};

/// All cells over seeds, in the order of the first seed's cells.
struct CellTable {
  int n_seeds = 0;
  std::vector<CellSummary> cells{};
  /// The cell named `pointer`, or nullptr.
  [[nodiscard]] const CellSummary* find(std::string_view pointer) const;
};

/// Mean and sd of every cell over `per_seed` (each the output of reproduction_cells). Throws
/// InputError when the seeds' cells do not line up or a key cell differs between seeds.
CellTable summarize_cells(const std::vector<std::vector<Cell>>& per_seed);

}  // namespace vrreg::experiments
