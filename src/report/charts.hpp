// SPDX-License-Identifier: Apache-2.0
#pragma once
// Building blocks of the report's Plotly charts: layouts whose axis titles carry units, traces
// from histograms and per-target errors, and the colours every chart shares.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/metrics/rigid_body.hpp"

namespace vrreg::report::charts {

inline constexpr const char* kUncorrected = "#5b6270";  ///< uncorrected errors: grey
inline constexpr const char* kCorrected = "#1f77b4";    ///< RRBC-corrected errors: blue
inline constexpr const char* kFailed = "#d62728";       ///< where RRBC failed (N_bad): red
inline constexpr const char* kPaper = "#ff7f0e";        ///< the paper's numbers: orange
inline constexpr const char* kNeutral = "#9aa3b2";      ///< context (fiducials, successes)

/// A value rounded to `decimals` places (smaller pages, clean hover values).
double round_to(double value, int decimals);

/// Values times `scale` (e.g. 1000 for m -> mm), rounded, as a JSON array.
nlohmann::json scaled(const Eigen::Ref<const Eigen::VectorXd>& values, double scale, int decimals);
nlohmann::json scaled(const std::vector<double>& values, double scale, int decimals);

/// A 2D layout with axis titles (units in the titles, e.g. "L [mm]").
nlohmann::json xy_layout(const std::string& x_title, const std::string& y_title);

/// A 3D layout (scene) with axis titles, drawn to the data's proportions.
nlohmann::json scene_layout(const std::string& x_title, const std::string& y_title,
                            const std::string& z_title);

/// A bar trace of `h` with bin centres times `scale`: counts per bin.
nlohmann::json histogram_trace(const Histogram& h, double scale, const std::string& name,
                               const std::string& color);

/// Whole-number ticks on the count axis of `layout` when `h` holds few counts (no "2.5 targets").
void whole_count_ticks(nlohmann::json& layout, const Histogram& h);

/// A step-line trace of `h` (several histograms overlaid in one chart, paper Fig. 5-6).
nlohmann::json histogram_step_trace(const Histogram& h, double scale, const std::string& name);

/// A bar trace of per-target values [mm] against target number n = 1..N, hover showing labels.
nlohmann::json per_target_trace(const std::vector<double>& values_mm,
                                const std::vector<std::string>& labels, const std::string& name,
                                const std::string& color);

/// A 3D marker trace of points [m] drawn in mm, hover showing labels; `marker` as Plotly's.
nlohmann::json scatter3d_trace(const Points3& points_m, const std::vector<std::string>& labels,
                               const std::string& name, const nlohmann::json& marker);

/// Equal bins over [lo, hi) holding every value: about `target_bins` bins of a rounded width.
Histogram auto_histogram(const Eigen::Ref<const Eigen::VectorXd>& values, int target_bins);

}  // namespace vrreg::report::charts
