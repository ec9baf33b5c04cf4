// SPDX-License-Identifier: Apache-2.0
#pragma once
// `vrreg reproduce` as text: Table 1, the Figure 7-8 data and Table 2 beside the paper's numbers
// (paper_numbers.hpp), mean +- sd over seeds when there are several, and the findings.
#include <string>
#include <vector>

#include "vrreg/experiments/findings.hpp"
#include "vrreg/experiments/reproduction_cells.hpp"

namespace vrreg::experiments {

/// Table 1 (A1, A2), Figures 7-8 (dataset B) and Table 2 (KUKA), each row beside the paper's;
/// tables whose cells are absent are left out.
std::string format_reproduction_tables(const CellTable& cells);

/// The findings of one seed: statement, value, met / not met.
std::string format_findings(const std::vector<Finding>& findings);

/// The findings over seeds: on how many seeds each held and whether that is >= 80 %.
std::string format_finding_rates(const std::vector<FindingRate>& rates,
                                 const std::vector<Finding>& first_seed);

}  // namespace vrreg::experiments
