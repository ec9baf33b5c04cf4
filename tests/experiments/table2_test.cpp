// SPDX-License-Identifier: Apache-2.0
// Table 2's runner on the two-arm cell (tests/support/two_arm_cell.hpp): the IK swaps its listing
// for x >= 40 mm, so Strategy 2 switches 3/5 of the points and Strategies 2 and 3 correct better
// than Strategy 1 in both configurations; Strategy 1 equals a registration per file label.
#include "vrreg/experiments/table2.hpp"

#include <sstream>

#include "two_arm_cell.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/registration/rigid.hpp"
#include "vrreg_test.hpp"

namespace vrreg::experiments {
namespace {

MeasurementSet cell() {
  std::istringstream in(testing::two_arm_cell_csv());
  return io::parse_measurement_csv(in, "cell.csv");
}

TEST(Table2, TwoArmCell) {
  Table2Options options;
  options.sigma_opt_m = 0.005e-3;
  options.strategy3_seed = 7;
  options.l_histogram_bin_m = 0.01e-3;
  const MeasurementSet set = cell();
  const Table2 t = run_table2(set, options);
  EXPECT_EQ(t.configs, (std::vector<int>{1, 2}));
  EXPECT_DOUBLE_EQ(t.strategy2.switched_points_fraction(), 0.6);
  EXPECT_DOUBLE_EQ(t.strategy2.switched_locations_fraction(), 0.6);
  EXPECT_TRUE(t.switched(1));
  EXPECT_TRUE(t.switched(2));
  EXPECT_FALSE(t.switched(3));
  EXPECT_NEAR(t.sigma_noise_m, std::hypot(0.005e-3, 0.05e-3), 1e-15);
  ASSERT_EQ(t.entries.size(), 6u);
  ASSERT_EQ(t.strategy3_corners.size(), 8u);
  for (const int m : t.configs) {
    const RrbcRunFigures& s1 = t.at(m, 1).figures;
    const RrbcRunFigures& s2 = t.at(m, 2).figures;
    const RrbcRunFigures& s3 = t.at(m, 3).figures;
    EXPECT_EQ(s1.n_targets, 8);
    EXPECT_EQ(s3.n_targets, 8);
    EXPECT_EQ(s3.n_fiducials, 8);
    EXPECT_EQ(s1.n_flagged + s2.n_flagged + s3.n_flagged, 0);
    EXPECT_LT(s2.cor_rms_t_m, s1.cor_rms_t_m) << m;
    EXPECT_LT(s3.cor_rms_t_m, s1.cor_rms_t_m) << m;
    EXPECT_LT(s2.sigma_l_m, s1.sigma_l_m) << m;
    EXPECT_DOUBLE_EQ(s3.sigma_l_m, 0.0);
    EXPECT_GT(s3.gamma, s2.gamma) << m;
    EXPECT_TRUE(s1.l_histogram.has_value());
    EXPECT_FALSE(s3.l_histogram.has_value());
    EXPECT_EQ(t.at(m, 1).target_points.size(), 8u);
  }
  // Strategy 1, configuration 1: the registration of the file's label-1 fiducials.
  const std::vector<std::size_t> fid = set.select(Role::kFiducial, 1);
  const std::vector<std::size_t> tgt = set.select(Role::kTarget, 1);
  const SimilarityTransform T =
      register_rigid(set.sensor_points(fid), set.robot_points(fid)).T_robot_sensor;
  const Eigen::VectorXd unc =
      (T.apply_all(set.sensor_points(tgt)) - set.robot_points(tgt)).colwise().norm().transpose();
  EXPECT_EIGEN_NEAR(t.at(1, 1).figures.unc_tre_m, unc, 1e-12);
  EXPECT_THROW((void)t.at(5, 1), InputError);
}

TEST(Table2, NeedsConfigurations) {
  std::istringstream in(testing::two_arm_cell_csv({.with_config = false}));
  EXPECT_THROW(run_table2(io::parse_measurement_csv(in, "cell.csv"), {}), InputError);
}

}  // namespace
}  // namespace vrreg::experiments
