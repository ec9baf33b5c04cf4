// SPDX-License-Identifier: Apache-2.0
// The cells extrapolation and the joint model's gaps are judged on (docs/uncertainty.md): far
// targets where they are said to be, the same cell for the same seed; an arm on a rail whose
// carriage slides the UR5's base along x and ripples between positions.
#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/dh.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/simulation/far_field_cells.hpp"
#include "vrreg/simulation/rail_cell.hpp"
#include "vrreg_test.hpp"

namespace vrreg::simulation {
namespace {

// The distance of `p_m` from the box of `points_m` [m].
double beyond_box_m(const Eigen::Vector3d& p_m, const Points3& points_m) {
  const Eigen::Vector3d lo = points_m.rowwise().minCoeff();
  const Eigen::Vector3d hi = points_m.rowwise().maxCoeff();
  return (p_m - p_m.cwiseMax(lo).cwiseMin(hi)).norm();
}

TEST(FarFieldCells, TargetsLieTheirDistanceBeyondTheLatticeAndSeedsRepeat) {
  FarFieldCellOptions o;
  o.nodes = 4;
  o.spacing_m = 0.02;
  for (const FarPhysics physics : {FarPhysics::kTrackerWarp, FarPhysics::kTrackerScale}) {
    o.physics = physics;
    const FarFieldCell cell = far_field_cell(o);
    ASSERT_EQ(cell.fiducials_robot_m.cols(), 64);
    ASSERT_EQ(cell.targets_robot_m.cols(), 24);
    const double size_m = 0.06;
    for (Eigen::Index t = 0; t < cell.targets_robot_m.cols(); ++t) {
      const double d = cell.target_distance[static_cast<std::size_t>(t)];
      const double beyond_m = beyond_box_m(cell.targets_robot_m.col(t), cell.fiducials_robot_m);
      EXPECT_NEAR(beyond_m, d * size_m, 1e-9 * d * size_m) << t;
    }
    const FarFieldCell again = far_field_cell(o);
    EXPECT_EQ(again.targets_sensor_m, cell.targets_sensor_m);
  }
  o.nodes = 1;
  EXPECT_THROW((void)far_field_cell(o), InputError);
}

TEST(RailCell, TheCarriageSlidesTheArmAlongXAndRipplesBetweenPositions) {
  const kinematics::SerialChain rail = ur5_on_rail();
  ASSERT_EQ(rail.n_joints(), 7);
  EXPECT_TRUE(rail.prismatic(0));
  kinematics::JointVector q(7);
  q << 0.4, 0.3, -1.2, 1.5, -1.9, -1.57, 0.4;
  kinematics::JointVector moved = q;
  moved(0) += 0.25;
  const Eigen::Vector3d step =
      kinematics::forward_kinematics(rail, moved).translation() -
      kinematics::forward_kinematics(rail, q).translation();
  EXPECT_EIGEN_NEAR(step, Eigen::Vector3d(0.25, 0.0, 0.0), 1e-12);

  RailCellOptions o;
  o.targets = 10;
  const RailCell cell = rail_cell(o);
  ASSERT_EQ(cell.fiducials_robot_m.cols(), 3 * 45);
  ASSERT_EQ(cell.targets_robot_m.cols(), 10);
  for (Eigen::Index j = 0; j < cell.fiducials_robot_m.cols(); ++j) {
    // Commanded joints and nominal positions agree: the robot is the cell's.
    EXPECT_LT((kinematics::forward_kinematics(cell.robot, cell.fiducials_q_rad.col(j)).translation() -
               cell.fiducials_robot_m.col(j)).norm(),
              1e-9);
  }
  for (Eigen::Index t = 0; t < 10; ++t) {
    EXPECT_GE(cell.targets_q_rad(0, t), o.target_lo_m);
    EXPECT_LE(cell.targets_q_rad(0, t), o.target_hi_m);
  }
  // The ripple is the carriage's only error difference: with it off, the readings change by up
  // to its amplitude and no more.
  RailCellOptions smooth = o;
  smooth.ripple_amplitude_m = 0.0;
  const RailCell without = rail_cell(smooth);
  const double change_m =
      (cell.targets_sensor_m - without.targets_sensor_m).colwise().norm().maxCoeff();
  EXPECT_GT(change_m, 0.02e-3);
  EXPECT_LT(change_m, 0.15e-3 + 1e-9);
}

}  // namespace
}  // namespace vrreg::simulation
