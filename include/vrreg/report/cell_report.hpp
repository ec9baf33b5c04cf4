// SPDX-License-Identifier: Apache-2.0
#pragma once
// The report of a user's own cell (`vrreg report --model M --targets T`): the paper's
// kinds of figures for their data (L histogram, TRE per target, RMS_T per configuration, the 3D
// volume with RRBC's failures, the Delta TRE histogram) and a verdict in words (rho against 2.5,
// gamma, N_bad and where the bad targets are).
#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/metrics/improvement.hpp"
#include "vrreg/metrics/noise.hpp"
#include "vrreg/metrics/rigid_body.hpp"
#include "vrreg/metrics/rigid_body_sampled.hpp"
#include "vrreg/pipeline/evaluate.hpp"
#include "vrreg/pipeline/model.hpp"
#include "vrreg/report/page.hpp"

namespace vrreg::report {

/// What was evaluated: the model, and its evaluation on the targets (vrreg::evaluate).
struct CellReportInput {
  const RegistrationModel& model;
  const EvaluateResult& evaluation;
  std::string model_name{};    ///< the model file as named by the user
  std::string targets_name{};  ///< the targets file as named by the user
  /// Robot repeatability for sigma_noise (Eq. 9) [m]; empty: the one stored in the model, if any.
  std::optional<double> sigma_rep_m{};
};

/// The numbers behind the cell report.
struct CellAnalysis {
  int n_fiducials = 0;
  RigidBodyStatistics rigid_body{};   ///< L_ij over the model's fiducial pairs (Eq. 1)
  Histogram l_histogram{};            ///< of L_ij [m]
  SigmaLSampling sigma_l_sampling{};  ///< above 20 000 fiducials: both from sampled pairs
  NoiseFigures noise{};  ///< sigma_opt (repeat readings), sigma_rep, sigma_noise, rho (Eq. 9)
  std::string method{};  ///< Procedure 2 in words, e.g. "Strategy 2 (l2 joint distance)"; or empty
  Points3 targets_robot_m{};          ///< nominal robot-frame positions of the targets
  std::vector<std::string> labels{};  ///< target labels, "T1" or "T1 (config 2)"
  std::vector<std::optional<int>> configs{};
  Eigen::VectorXd unc_tre_m{};   ///< TRE(T_X) per target (Eq. 3)
  Eigen::VectorXd cor_tre_m{};   ///< TRE(T^_X) per target (flagged: uncorrected)
  ImprovementSummary summary{};  ///< RMS_T, gamma, N_bad, Delta TRE
  std::string where_bad{};       ///< describe_locations of the bad targets
};

/// Computes the cell's figures: rigid-body statistics and histogram, noise, errors, summary.
CellAnalysis analyze_cell(const CellReportInput& input);

/// Where a subset of targets lies, in words: by z layer when the targets form layers (e.g. "3 of
/// 4 on the lowest layer (z = 175.0 mm), 1 on the top layer (z = 375.0 mm)"), else by thirds of
/// the z range, and how many lie on the boundary of the targets' bounding box. points_robot_m:
/// all targets [m]; subset: indices into them. Empty for an empty subset.
std::string describe_locations(const Points3& points_robot_m, const std::vector<int>& subset);

/// The verdict in words (also printed by the command line).
std::vector<ReportVerdict> cell_verdict(const CellReportInput& input, const CellAnalysis& a);

/// The whole page.
ReportPage cell_report_page(const CellReportInput& input, const CellAnalysis& a);

}  // namespace vrreg::report
