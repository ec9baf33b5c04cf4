// SPDX-License-Identifier: Apache-2.0
// Procedure 2 end to end (paper section 4.4) on a small synthetic cell whose robot error depends
// on the arm configuration and whose IK changes its listing order half way: Strategies 2 and 3
// correct targets better than Strategy 1, in every configuration.
#include <gtest/gtest.h>

#include <sstream>

#include "two_arm_cell.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/rrbc.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/planning/strategy2_labels.hpp"
#include "vrreg/planning/strategy3_correction.hpp"
#include "vrreg/planning/strategy3_registration.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg {
namespace {

constexpr double kCubeEdgeM = 0.040;

MeasurementSet cell() {
  std::istringstream in(testing::two_arm_cell_csv());
  return io::parse_measurement_csv(in, "cell.csv");
}

std::vector<Location> pick(const MeasurementSet& set, const std::vector<std::size_t>& rows) {
  std::vector<Location> out;
  for (const std::size_t i : rows) out.push_back(set.locations[i]);
  return out;
}

// Corrected RMS_T of the targets in `config` with a registration of that configuration
// (Strategies 1 and 2: the labels of `set` decide).
double per_label_cor_rms_t(const MeasurementSet& set, int config) {
  const std::vector<std::size_t> fid = set.select(Role::kFiducial, config);
  const std::vector<std::size_t> tgt = set.select(Role::kTarget, config);
  CorrectionField model;
  model.T_robot_sensor =
      register_rigid(set.sensor_points(fid), set.robot_points(fid)).T_robot_sensor;
  model.fiducials_robot_m = set.robot_points(fid);
  model.corrections_sensor_m =
      fiducial_corrections(model.T_robot_sensor, set.sensor_points(fid), set.robot_points(fid));
  InterpolationSettings settings;
  settings.method = InterpolationMethod::kOctuplet;
  settings.cube_edge_m = kCubeEdgeM;
  const TargetCorrection c =
      correct_targets(model, set.sensor_points(tgt), set.robot_points(tgt), settings);
  EXPECT_EQ(c.n_flagged, 0);
  return root_mean_square(point_errors(c.corrected_robot_m, set.robot_points(tgt)));
}

double strategy3_cor_rms_t(const MeasurementSet& set, int config, std::uint64_t seed) {
  const std::vector<std::size_t> fid = set.select(Role::kFiducial);
  const std::vector<std::size_t> tgt = set.select(Role::kTarget, config);
  planning::Strategy3Options options;
  options.seed = seed;
  const std::vector<Location> fiducials = pick(set, fid);
  const planning::Strategy3Registration r = planning::register_volume_corners(fiducials, options);
  planning::Strategy3CorrectionOptions correction;
  correction.cube_edge_m = kCubeEdgeM;
  const TargetCorrection c = planning::correct_targets_strategy3(
      r.registration.T_robot_sensor, fiducials, r.corrections_sensor_m, pick(set, tgt), correction);
  EXPECT_EQ(c.n_flagged, 0);
  return root_mean_square(point_errors(c.corrected_robot_m, set.robot_points(tgt)));
}

TEST(Procedure2, Strategy2SwitchesTheSwappedRegionOnly) {
  const planning::Strategy2Result r = planning::relabel_strategy2(cell());
  EXPECT_EQ(r.summary.n_points, 125);
  EXPECT_EQ(r.summary.n_locations, 250);
  EXPECT_EQ(r.summary.n_switched, 150);  // x >= 40 mm: 3 of 5 grid planes
  EXPECT_EQ(r.summary.n_switched_points, 75);
  EXPECT_DOUBLE_EQ(r.summary.switched_locations_fraction(), 0.6);
  EXPECT_DOUBLE_EQ(r.summary.switched_points_fraction(), 0.6);
  EXPECT_EQ(r.summary.switched_by_file_label, (std::map<int, int>{{1, 75}, {2, 75}}));
  for (const Location& loc : r.set.locations) {  // label 1 is arm A everywhere
    const bool arm_b = testing::two_arm_joints(loc.robot_m * 1000.0, true)
                           .isApprox(Eigen::Map<const Eigen::VectorXd>(loc.q_rad.data(), 7), 1e-9);
    EXPECT_EQ(*loc.config, arm_b ? 2 : 1) << loc.point;
  }
  const planning::Strategy2Result linf =
      planning::relabel_strategy2(cell(), kinematics::JointNorm::kLinf);
  EXPECT_EQ(linf.summary.n_switched, 150);
}

TEST(Procedure2, Strategies2And3CorrectBetterThanStrategy1) {
  const MeasurementSet listed = cell();
  const MeasurementSet ordered = planning::relabel_strategy2(listed).set;
  for (int config = 1; config <= 2; ++config) {
    const double s1 = per_label_cor_rms_t(listed, config);
    const double s2 = per_label_cor_rms_t(ordered, config);
    const double s3 = strategy3_cor_rms_t(listed, config, 1);
    EXPECT_LT(s2, 0.5 * s1) << "config " << config << ": " << s1 << " vs " << s2;
    EXPECT_LT(s3, 0.5 * s1) << "config " << config << ": " << s1 << " vs " << s3;
    EXPECT_LT(s2, 0.1e-3);
  }
  for (std::uint64_t seed = 2; seed <= 5; ++seed) {  // whichever corners the seed picks
    EXPECT_LT(strategy3_cor_rms_t(listed, 1, seed), 0.5 * per_label_cor_rms_t(listed, 1));
  }
}

}  // namespace
}  // namespace vrreg
