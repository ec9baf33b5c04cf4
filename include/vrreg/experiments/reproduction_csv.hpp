// SPDX-License-Identifier: Apache-2.0
#pragma once
// The data of the reproduced tables and figures as CSV text (mm, percent), one file each:
// Table 1, Figures 7-8 and Table 2 (= Figures 14-15) from the cells (mean and sd over seeds, paper
// beside); Figures 4-6 (L histograms), 10 (targets), 11 (Delta TRE histogram) and 12-13 (TRE per
// target) from one seed's reproduction.
#include <string>

#include "vrreg/experiments/reproduction.hpp"
#include "vrreg/experiments/reproduction_cells.hpp"

namespace vrreg::experiments {

/// table1.csv: rows vrreg, vrreg_sd, paper per dataset; columns as Table 1.
std::string table1_csv(const CellTable& cells);
/// figure7_8.csv: per cube size d, cube edge, cor RMS_T, N_bad, gamma (with sd) and the paper's.
std::string figure7_8_csv(const CellTable& cells);
/// table2.csv: per configuration and strategy, as Table 2 (with sd) and the paper's.
std::string table2_csv(const CellTable& cells);
/// histograms_l.csv: L histograms of A1, A2 (Fig. 4) and the KUKA per strategy and configuration
/// (Fig. 5, 6): bin edges and counts.
std::string histograms_l_csv(const Reproduction& r);
/// figure10_targets.csv: dataset B's targets, their errors at d_max and d_min and where RRBC
/// failed (Fig. 9, 10).
std::string figure10_targets_csv(const Reproduction& r);
/// figure11_delta_tre.csv: histogram of Delta TRE < 0 at d_min (Fig. 11).
std::string figure11_delta_tre_csv(const Reproduction& r);
/// tre_per_target.csv: the KUKA targets' uncorrected and corrected TRE per strategy and
/// configuration (Fig. 12, 13).
std::string tre_per_target_csv(const Reproduction& r);

}  // namespace vrreg::experiments
