// SPDX-License-Identifier: Apache-2.0
#pragma once
// Beyond the paper as cells (reproduction_cells.hpp: "/beyond/<dataset>/<method>/cor_rms_t_mm"
// ...), as text (one table per dataset) and as beyond.csv; mean +- sd over seeds like the others.
#include <string>
#include <vector>

#include "vrreg/experiments/beyond_paper.hpp"
#include "vrreg/experiments/reproduction_cells.hpp"

namespace vrreg::experiments {

/// Appends the cells of `tables` (one seed) to `out`: per dataset n_fiducials, n_targets,
/// unc_rms_t_mm, noise_floor_mm; per method cor_rms_t_mm, over_floor, calibration_rms_ratio,
/// within_2sigma_percent, n_flagged (NaN where the method gave nothing) and for auto
/// chose_<method> (1 or 0: over seeds, the fraction of seeds it chose that method).
void append_beyond_cells(const std::vector<BeyondTable>& tables, std::vector<Cell>& out);

/// The beyond tables of `cells` (empty when there are none); `first_seed` gives the method names
/// and, for rows without numbers, why (e.g. "kriging interpolation is not built yet").
std::string format_beyond_tables(const CellTable& cells, const std::vector<BeyondTable>& first_seed);

/// The orientation tables of the datasets with a rigid-body marker (per dataset: unc RMS angle,
/// its noise floor; per method: cor RMS angle, over the floor, angle / predicted sd) [mrad];
/// empty when none has orientations. Part of format_beyond_tables.
std::string format_beyond_orientation(const CellTable& cells,
                                      const std::vector<BeyondTable>& first_seed);

/// beyond.csv: one line per dataset and method, mean and sd over seeds (mm, percent).
std::string beyond_csv(const CellTable& cells, const std::vector<BeyondTable>& first_seed);

}  // namespace vrreg::experiments
