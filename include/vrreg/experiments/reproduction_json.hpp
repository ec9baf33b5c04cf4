// SPDX-License-Identifier: Apache-2.0
#pragma once
// `vrreg reproduce --json` and reproduce.json (format "vrreg-reproduce", version 1): the cells of
// Table 1, dataset B / Figure 7, the KUKA summary and Table 2 (numbers for one seed, {"mean",
// "sd"} objects over several), the findings, and the first seed's figure data (L histograms,
// per-target errors) for `vrreg report`.
#include <nlohmann/json.hpp>
#include <vector>

#include "vrreg/experiments/findings.hpp"
#include "vrreg/experiments/reproduction.hpp"
#include "vrreg/experiments/reproduction_cells.hpp"

namespace vrreg::experiments {

inline constexpr const char* kReproductionJsonFormat = "vrreg-reproduce";
inline constexpr int kReproductionJsonVersion = 1;

/// The whole document for `runs` (one per seed, in seed order; at least one).
nlohmann::json reproduction_json(const std::vector<Reproduction>& runs);

/// The cells as a nested object addressed by their JSON pointers (see reproduction_cells.hpp).
nlohmann::json cells_json(const CellTable& cells);

/// l_histograms and target_errors entries of one seed (Fig. 4-6, 10-13).
nlohmann::json figure_data_json(const Reproduction& r);

}  // namespace vrreg::experiments
