#include "vrreg/registration/marker_offset.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::random_transform;

// A hand-eye layout: flange positions in a 0.3 m box, the tool pointing down, tilted by up to
// `tilt_rad` about the robot x and y axes (two axes, as the hand-eye literature recommends).
std::vector<Eigen::Isometry3d> tilted_flange_poses(Random& rng, int n, double tilt_rad) {
  std::vector<Eigen::Isometry3d> poses;
  for (int j = 0; j < n; ++j) {
    Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
    f.linear() = (Eigen::AngleAxisd(rng.uniform(-tilt_rad, tilt_rad), Eigen::Vector3d::UnitX()) *
                  Eigen::AngleAxisd(rng.uniform(-tilt_rad, tilt_rad), Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
    f.translation() = Eigen::Vector3d(0.45, 0.0, 0.25) + testing::random_points(rng, 1, 0.15);
    poses.push_back(f);
  }
  return poses;
}

struct Cell {
  RigidTransform T_robot_sensor;
  Eigen::Vector3d p_flange_marker_m{0.035, -0.025, 0.085};
  std::vector<Eigen::Isometry3d> flange;
};

// Marker positions the sensor reads, with Gaussian noise per sensor axis [m].
Points3 sensor_readings(const Cell& cell, Random& rng, double sigma_m) {
  const RigidTransform T_sensor_robot = cell.T_robot_sensor.inverse();
  Points3 y(3, static_cast<Eigen::Index>(cell.flange.size()));
  for (std::size_t j = 0; j < cell.flange.size(); ++j) {
    y.col(static_cast<Eigen::Index>(j)) =
        T_sensor_robot.apply(cell.flange[j] * cell.p_flange_marker_m) + rng.normal3(sigma_m);
  }
  return y;
}

TEST(MarkerOffset, NoiseFreeRecoveryOfOffsetAndTransform) {
  Random rng(11);
  for (int trial = 0; trial < 30; ++trial) {
    Cell cell;
    cell.T_robot_sensor = random_transform(rng, 2.0);
    cell.p_flange_marker_m = testing::random_points(rng, 1, 0.1);
    cell.flange = tilted_flange_poses(rng, 6 + trial, 0.4);
    const Points3 y = sensor_readings(cell, rng, 0.0);
    const MarkerOffsetResult r = estimate_marker_offset(cell.flange, y);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_EIGEN_NEAR(r.p_flange_marker_m, cell.p_flange_marker_m, 1e-9);
    EXPECT_EIGEN_NEAR(r.T_robot_sensor.rotation, cell.T_robot_sensor.rotation, 1e-9);
    EXPECT_EIGEN_NEAR(r.T_robot_sensor.translation_m, cell.T_robot_sensor.translation_m, 1e-9);
    EXPECT_LT(r.fre_m, 1e-9);
    EXPECT_NEAR(r.T_robot_sensor.rotation.determinant(), 1.0, 1e-12);
  }
}

// Coplanar sensor points leave the linear start rank deficient: the alternating start takes over.
TEST(MarkerOffset, CoplanarPositionsStillRecovered) {
  Random rng(12);
  Cell cell;
  cell.T_robot_sensor = random_transform(rng, 2.0);
  cell.flange = tilted_flange_poses(rng, 12, 0.35);
  for (auto& f : cell.flange) f.translation().z() = 0.25;  // flange origins in one plane
  const Points3 y = sensor_readings(cell, rng, 0.0);
  const MarkerOffsetResult r = estimate_marker_offset(cell.flange, y);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EIGEN_NEAR(r.p_flange_marker_m, cell.p_flange_marker_m, 1e-9);
  EXPECT_EIGEN_NEAR(r.T_robot_sensor.translation_m, cell.T_robot_sensor.translation_m, 1e-9);
}

// The paper's layout: a grid visited at one fixed orientation. p cannot be told from tau.
TEST(MarkerOffset, FixedOrientationIsReportedUnobservable) {
  Random rng(13);
  Cell cell;
  cell.T_robot_sensor = random_transform(rng, 2.0);
  cell.flange = tilted_flange_poses(rng, 27, 0.0);
  const MarkerOffsetResult r = estimate_marker_offset(cell.flange, sensor_readings(cell, rng, 0.0));
  EXPECT_EQ(r.status, MarkerOffsetStatus::kUnobservable);
  EXPECT_LT(r.orientation_spread, 1e-6);
  EXPECT_NE(r.message.find("not observable"), std::string::npos);
}

// Tilts about one axis only: p along that axis is not observable either.
TEST(MarkerOffset, TiltsAboutOneAxisAreReportedUnobservable) {
  Random rng(14);
  Cell cell;
  cell.T_robot_sensor = random_transform(rng, 2.0);
  for (int j = 0; j < 20; ++j) {
    Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
    f.linear() = Eigen::AngleAxisd(rng.uniform(-0.5, 0.5), Eigen::Vector3d::UnitX()).matrix();
    f.translation() = testing::random_points(rng, 1, 0.15);
    cell.flange.push_back(f);
  }
  const MarkerOffsetResult r = estimate_marker_offset(cell.flange, sensor_readings(cell, rng, 0.0));
  EXPECT_EQ(r.status, MarkerOffsetStatus::kUnobservable);
}

TEST(MarkerOffset, BadInputThrows) {
  Random rng(15);
  Cell cell;
  cell.flange = tilted_flange_poses(rng, 4, 0.3);
  EXPECT_THROW(estimate_marker_offset(cell.flange, sensor_readings(cell, rng, 0.0)), InputError);
  cell.flange = tilted_flange_poses(rng, 8, 0.3);
  Points3 y = sensor_readings(cell, rng, 0.0);
  EXPECT_THROW(estimate_marker_offset(cell.flange, y.leftCols(7)), InputError);
  y(1, 3) = std::nan("");
  EXPECT_THROW(estimate_marker_offset(cell.flange, y), InputError);
}

// Monte Carlo over 100 seeds with tracker noise: the offset lies within 3 reported standard
// uncertainties, and the reported uncertainty matches the spread of the estimates to +-20 %.
TEST(MarkerOffset, ReportedUncertaintyMatchesMonteCarlo) {
  Random layout_rng(21);
  Cell cell;
  cell.T_robot_sensor = random_transform(layout_rng, 2.0);
  cell.flange = tilted_flange_poses(layout_rng, 40, 0.35);
  constexpr int kSeeds = 100;
  constexpr double kSigmaM = 0.1e-3;
  Eigen::Matrix3Xd estimates(3, kSeeds);
  Eigen::Vector3d reported_sq = Eigen::Vector3d::Zero();
  int within = 0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    Random rng(1000 + static_cast<std::uint64_t>(seed));
    const MarkerOffsetResult r =
        estimate_marker_offset(cell.flange, sensor_readings(cell, rng, kSigmaM));
    ASSERT_TRUE(r.ok()) << r.message;
    estimates.col(seed) = r.p_flange_marker_m;
    reported_sq += r.p_std_m.cwiseAbs2();
    const Eigen::Vector3d z =
        (r.p_flange_marker_m - cell.p_flange_marker_m).cwiseQuotient(r.p_std_m);
    for (int a = 0; a < 3; ++a) within += std::abs(z(a)) <= 3.0 ? 1 : 0;
    EXPECT_LE(z.cwiseAbs().maxCoeff(), 4.0) << "seed " << seed;
  }
  const Eigen::Vector3d mean = estimates.rowwise().mean();
  const Eigen::Vector3d spread =
      ((estimates.colwise() - mean).cwiseAbs2().rowwise().sum() / (kSeeds - 1)).cwiseSqrt();
  const Eigen::Vector3d reported = (reported_sq / kSeeds).cwiseSqrt();
  std::printf(
      "p std reported %.4f %.4f %.4f mm, Monte Carlo %.4f %.4f %.4f mm, %d/%d axes within 3 std\n",
      1e3 * reported.x(), 1e3 * reported.y(), 1e3 * reported.z(), 1e3 * spread.x(),
      1e3 * spread.y(), 1e3 * spread.z(), within, 3 * kSeeds);
  // 3 standard uncertainties hold 99.73 % of a Gaussian: at most 1 % of the 300 axis estimates
  // may fall outside (0.8 expected), none beyond 4.
  EXPECT_GE(within, 3 * kSeeds - 3);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(reported(a) / spread(a), 1.0, 0.2) << "axis " << a;
  }
  // The estimator is unbiased to well within the spread.
  EXPECT_LT(((mean - cell.p_flange_marker_m).cwiseQuotient(spread)).cwiseAbs().maxCoeff(),
            3.0 / std::sqrt(kSeeds) * 1.5);
}

}  // namespace
}  // namespace vrreg
