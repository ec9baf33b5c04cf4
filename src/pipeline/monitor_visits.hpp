// SPDX-License-Identifier: Apache-2.0
#pragma once
// Monitor points read then (the model) and today (a file), paired by (point, config): the mean of
// each one's visits and the scatter of the visits about their means.
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/pipeline/model.hpp"

namespace vrreg::pipeline_detail {

/// One monitor point read then and today (sensor frame of the registration) [m].
struct MonitorPair {
  std::string point;
  std::optional<int> config;
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d baseline_m = Eigen::Vector3d::Zero();  ///< mean of the visits at registration
  Eigen::Vector3d today_m = Eigen::Vector3d::Zero();     ///< mean of today's visits
  Eigen::Vector3d today_as_read_m = Eigen::Vector3d::Zero();  ///< the same in today's sensor frame
  int baseline_visits = 0;
  int today_visits = 0;
};

/// The visits' scatter about their means at one time, over the points read.
struct VisitScatter {
  double sum_m2 = 0.0;  ///< sum over points of |visit - its mean|^2
  double dof = 0.0;     ///< 3 (visits - 1) summed over points
};

/// The pairs in the model's order, with the visits' scatter then and today, apart (today may be
/// noisier than the registration).
struct MonitorPairs {
  std::vector<MonitorPair> points;
  VisitScatter then{};   ///< the registration's visits of the points read today
  VisitScatter today{};  ///< today's
  int model_points = 0;  ///< distinct monitor points the model has
};

/// Pairs today's monitor rows with the model's; throws InputError (the model's: the caller names
/// its file) when the model has none, and FileError naming today's file and line when today has
/// none or one the model does not have.
MonitorPairs monitor_pairs(const RegistrationModel& model, const MeasurementSet& today);

}  // namespace vrreg::pipeline_detail
