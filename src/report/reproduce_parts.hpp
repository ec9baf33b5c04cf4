// SPDX-License-Identifier: Apache-2.0
#pragma once
// The pieces of the reproduce report (report_reproduce*.cpp), each from reproduce.json.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "vrreg/report/page.hpp"
#include "vrreg/io/plan_csv.hpp"
#include "vrreg/metrics/rigid_body.hpp"

namespace vrreg::report::detail {

/// Table 1 (A1, A2) with the paper's rows beneath ours; empty rows when "table1" is absent.
ReportTable table1_beside_paper(const nlohmann::json& doc);
/// Table 2 (4 configurations x 3 strategies) beside the paper's.
ReportTable table2_beside_paper(const nlohmann::json& doc);
/// The paper's findings checked on these numbers.
std::vector<ReportVerdict> reproduce_findings(const nlohmann::json& doc);

/// Fig. 4 (L histogram, A2) into `table1`; Fig. 7, 8, 10, 11 (dataset B) into `b`. Names what is
/// missing in `missing`.
void add_ur5_figures(const nlohmann::json& doc, ReportSection& table1, ReportSection& b,
                     std::vector<std::string>& missing);
/// Fig. 10 (where RRBC failed at d_max and d_min) and Fig. 11 (Delta TRE at d_min) from dataset
/// B's target_errors entries, one per d.
void add_dataset_b_targets(const std::vector<nlohmann::json>& steps, ReportSection& b,
                           std::vector<std::string>& missing);
/// Fig. 5, 6 (L histograms), 12, 13 (TRE per target), 14, 15 (RMS_T per configuration).
void add_kuka_figures(const nlohmann::json& doc, ReportSection& kuka,
                      std::vector<std::string>& missing);
/// Fig. 16: a plan's part points and fiducials, in visiting order.
ReportFigure plan_layout_figure(const io::PlanFile& plan, const std::string& plan_name);

/// An l_histograms entry as a Histogram [m]; throws naming `where` when lo_mm, bin_mm or counts
/// is missing.
Histogram histogram_of(const nlohmann::json& entry, const std::string& where);

/// The entries of doc[key] (an array of objects) whose "dataset" is `dataset`.
std::vector<nlohmann::json> entries_of(const nlohmann::json& doc, const std::string& key,
                                       const std::string& dataset);

}  // namespace vrreg::report::detail
