// SPDX-License-Identifier: Apache-2.0
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


// Marker orientations the sensor reads: R_sensor_robot R_flange R_flange_marker, perturbed by a
// rotation with Gaussian small angles per marker axis [rad].
std::vector<Eigen::Quaterniond> sensor_orientations(const Cell& cell,
                                                    const Eigen::Matrix3d& R_flange_marker,
                                                    Random& rng, double sigma_rad) {
  std::vector<Eigen::Quaterniond> q;
  for (const Eigen::Isometry3d& f : cell.flange) {
    const Eigen::Vector3d noise = rng.normal3(sigma_rad);
    const Eigen::Matrix3d R = cell.T_robot_sensor.rotation.transpose() * f.linear() *
                              R_flange_marker *
                              Eigen::AngleAxisd(noise.norm(), noise.normalized()).toRotationMatrix();
    q.emplace_back(R);
  }
  return q;
}

TEST(MarkerOffsetWithOrientation, NoiseFreeRecoveryOfEverything) {
  Random rng(31);
  for (int trial = 0; trial < 20; ++trial) {
    Cell cell;
    cell.T_robot_sensor = random_transform(rng, 2.0);
    cell.p_flange_marker_m = testing::random_points(rng, 1, 0.1);
    cell.flange = tilted_flange_poses(rng, 5 + trial, 0.4);
    const Eigen::Matrix3d R_flange_marker = random_transform(rng, 1.0).rotation;
    const MarkerOffsetResult r =
        estimate_marker_offset(cell.flange, sensor_readings(cell, rng, 0.0),
                               sensor_orientations(cell, R_flange_marker, rng, 0.0));
    ASSERT_TRUE(r.ok()) << r.message;
    ASSERT_TRUE(r.has_marker_orientation);
    EXPECT_EIGEN_NEAR(r.p_flange_marker_m, cell.p_flange_marker_m, 1e-9);
    EXPECT_EIGEN_NEAR(r.T_robot_sensor.rotation, cell.T_robot_sensor.rotation, 1e-9);
    EXPECT_EIGEN_NEAR(r.T_robot_sensor.translation_m, cell.T_robot_sensor.translation_m, 1e-9);
    EXPECT_EIGEN_NEAR(r.q_flange_marker.toRotationMatrix(), R_flange_marker, 1e-9);
    EXPECT_LT(r.fre_m, 1e-9);
    EXPECT_LT(r.rotation_residuals_rad.maxCoeff(), 1e-9);
  }
}

// The rotation residuals do not involve p or tau: one flange orientation still leaves p
// unobservable, orientations or not.
TEST(MarkerOffsetWithOrientation, FixedOrientationStillUnobservable) {
  Random rng(32);
  Cell cell;
  cell.T_robot_sensor = random_transform(rng, 2.0);
  cell.flange = tilted_flange_poses(rng, 12, 0.0);
  const MarkerOffsetResult r = estimate_marker_offset(
      cell.flange, sensor_readings(cell, rng, 0.0),
      sensor_orientations(cell, Eigen::Matrix3d::Identity(), rng, 0.0));
  EXPECT_EQ(r.status, MarkerOffsetStatus::kUnobservable);
}

TEST(MarkerOffsetWithOrientation, BadInputThrows) {
  Random rng(33);
  Cell cell;
  cell.T_robot_sensor = random_transform(rng, 2.0);
  cell.flange = tilted_flange_poses(rng, 8, 0.3);
  const Points3 y = sensor_readings(cell, rng, 0.0);
  std::vector<Eigen::Quaterniond> q =
      sensor_orientations(cell, Eigen::Matrix3d::Identity(), rng, 0.0);
  q.pop_back();
  EXPECT_THROW(estimate_marker_offset(cell.flange, y, q), InputError);
  q.emplace_back(0.0, 0.0, 0.0, 0.0);
  EXPECT_THROW(estimate_marker_offset(cell.flange, y, q), InputError);
  q.back() = Eigen::Quaterniond(std::nan(""), 0.0, 0.0, 1.0);
  EXPECT_THROW(estimate_marker_offset(cell.flange, y, q), InputError);
}

// Monte Carlo over 100 seeds, position noise 0.1 mm, orientation noise 0.1 or 0.01 degree: p
// within 3 reported standard uncertainties, reported uncertainty of p and of R_flange_marker
// within +-20 % of the spread, both noises estimated to +-20 %; and on the same 12 poses the
// positions-only estimate of p is less certain (clearly so only for the precise tracker: the
// orientations fix R_robot_sensor better, which p depends on only weakly).
void check_orientation_monte_carlo(double sigma_deg) {
  Random layout_rng(41);
  Cell cell;
  cell.T_robot_sensor = random_transform(layout_rng, 2.0);
  cell.flange = tilted_flange_poses(layout_rng, 12, 0.35);
  const Eigen::Matrix3d R_flange_marker = random_transform(layout_rng, 1.0).rotation;
  constexpr int kSeeds = 100;
  constexpr double kSigmaM = 0.1e-3;
  const double kSigmaRad = sigma_deg * M_PI / 180.0;
  Eigen::Matrix3Xd p_with(3, kSeeds);
  Eigen::Matrix3Xd p_without(3, kSeeds);
  Eigen::Matrix3Xd angle_with(3, kSeeds);
  Eigen::Vector3d reported_with_sq = Eigen::Vector3d::Zero();
  Eigen::Vector3d reported_without_sq = Eigen::Vector3d::Zero();
  Eigen::Vector3d reported_angle_sq = Eigen::Vector3d::Zero();
  double sigma_m_sum = 0.0;
  double sigma_rad_sum = 0.0;
  int within = 0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    Random rng(2000 + static_cast<std::uint64_t>(seed));
    const Points3 y = sensor_readings(cell, rng, kSigmaM);
    const auto q = sensor_orientations(cell, R_flange_marker, rng, kSigmaRad);
    const MarkerOffsetResult with = estimate_marker_offset(cell.flange, y, q);
    const MarkerOffsetResult without = estimate_marker_offset(cell.flange, y);
    ASSERT_TRUE(with.ok()) << with.message;
    ASSERT_TRUE(without.ok()) << without.message;
    p_with.col(seed) = with.p_flange_marker_m;
    p_without.col(seed) = without.p_flange_marker_m;
    // Orientation error in flange axes (small angles), the parametrisation of the covariance.
    const Eigen::AngleAxisd error(R_flange_marker.transpose() *
                                  with.q_flange_marker.toRotationMatrix());
    angle_with.col(seed) = error.angle() * error.axis();
    reported_with_sq += with.p_std_m.cwiseAbs2();
    reported_without_sq += without.p_std_m.cwiseAbs2();
    reported_angle_sq += with.marker_rotation_std_rad.cwiseAbs2();
    sigma_m_sum += with.sigma_m;
    sigma_rad_sum += with.sigma_rad;
    const Eigen::Vector3d z =
        (with.p_flange_marker_m - cell.p_flange_marker_m).cwiseQuotient(with.p_std_m);
    for (int a = 0; a < 3; ++a) within += std::abs(z(a)) <= 3.0 ? 1 : 0;
    EXPECT_LE(z.cwiseAbs().maxCoeff(), 4.0) << "seed " << seed;
  }
  const auto spread_of = [kSeeds](const Eigen::Matrix3Xd& x, const Eigen::Vector3d& truth) {
    return Eigen::Vector3d(((x.colwise() - truth).cwiseAbs2().rowwise().sum() / kSeeds).cwiseSqrt());
  };
  const Eigen::Vector3d spread_with = spread_of(p_with, cell.p_flange_marker_m);
  const Eigen::Vector3d spread_without = spread_of(p_without, cell.p_flange_marker_m);
  const Eigen::Vector3d spread_angle = spread_of(angle_with, Eigen::Vector3d::Zero());
  const Eigen::Vector3d reported_with = (reported_with_sq / kSeeds).cwiseSqrt();
  const Eigen::Vector3d reported_without = (reported_without_sq / kSeeds).cwiseSqrt();
  const Eigen::Vector3d reported_angle = (reported_angle_sq / kSeeds).cwiseSqrt();
  std::printf(
      "12 poses, 0.1 mm, %.2f deg: p std with orientations reported %.4f %.4f %.4f mm, MC %.4f "
      "%.4f %.4f mm; positions only reported %.4f %.4f %.4f mm, MC %.4f %.4f %.4f mm; "
      "R_flange_marker std reported %.4f %.4f %.4f deg, MC %.4f %.4f %.4f deg; sigma %.4f mm "
      "%.4f deg; %d/%d axes within 3 std\n",
      sigma_deg,
      1e3 * reported_with.x(), 1e3 * reported_with.y(), 1e3 * reported_with.z(),
      1e3 * spread_with.x(), 1e3 * spread_with.y(), 1e3 * spread_with.z(),
      1e3 * reported_without.x(), 1e3 * reported_without.y(), 1e3 * reported_without.z(),
      1e3 * spread_without.x(), 1e3 * spread_without.y(), 1e3 * spread_without.z(),
      reported_angle.x() * 180 / M_PI, reported_angle.y() * 180 / M_PI,
      reported_angle.z() * 180 / M_PI, spread_angle.x() * 180 / M_PI,
      spread_angle.y() * 180 / M_PI, spread_angle.z() * 180 / M_PI, 1e3 * sigma_m_sum / kSeeds,
      sigma_rad_sum / kSeeds * 180 / M_PI, within, 3 * kSeeds);
  EXPECT_GE(within, 3 * kSeeds - 3);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(reported_with(a) / spread_with(a), 1.0, 0.2) << "axis " << a;
    EXPECT_NEAR(reported_angle(a) / spread_angle(a), 1.0, 0.2) << "axis " << a;
    EXPECT_LT(reported_with(a), reported_without(a) * (sigma_deg < 0.05 ? 1.0 : 1.001))
        << "axis " << a;
  }
  if (sigma_deg < 0.05) {
    EXPECT_LT(spread_with.norm(), spread_without.norm());
  }
  EXPECT_NEAR(sigma_m_sum / kSeeds / kSigmaM, 1.0, 0.2);
  EXPECT_NEAR(sigma_rad_sum / kSeeds / kSigmaRad, 1.0, 0.2);
}

TEST(MarkerOffsetWithOrientation, ReportedUncertaintyMatchesMonteCarloCoarseTracker) {
  check_orientation_monte_carlo(0.1);
}

TEST(MarkerOffsetWithOrientation, ReportedUncertaintyMatchesMonteCarloPreciseTracker) {
  check_orientation_monte_carlo(0.01);
}

}  // namespace
}  // namespace vrreg
