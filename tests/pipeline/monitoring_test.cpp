// SPDX-License-Identifier: Apache-2.0
// check_cell and update_model on a cell made here: fiducials on a grid with a smooth residual
// field, three monitor points read in visits. Exact references: a bump applied to noise-free
// readings is undone to rounding, an affine drift is recovered to rounding.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "vrreg/core/file_error.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/vrreg.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

// The tracker sees the robot frame rotated and 2 m away; the robot misses each command by a
// smooth field of ~0.3 mm.
RigidTransform tracker() {
  return RigidTransform(
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 1.0, -0.3).normalized()).toRotationMatrix(),
      Eigen::Vector3d(0.3, -0.2, 2.0));
}

Eigen::Vector3d actual(const Eigen::Vector3d& p) {
  return p + 3e-4 * Eigen::Vector3d(std::sin(9 * p.x()), std::cos(7 * p.y()), std::sin(5 * p.z()));
}

Location reading(const std::string& name, Role role, const Eigen::Vector3d& robot_m,
                 const RigidTransform& T_sensor_robot, Random* rng, std::optional<int> visit) {
  Location l;
  l.point = name;
  l.role = role;
  l.visit = visit;
  l.robot_m = robot_m;
  l.sensor_m = T_sensor_robot.apply(actual(robot_m));
  if (rng) l.sensor_m += rng->normal3(2e-5);
  l.n_readings = 1;
  l.source_line = 0;
  return l;
}

const Eigen::Vector3d kMonitors[] = {{0.40, -0.12, 0.10}, {0.60, 0.12, 0.30}, {0.50, 0.10, 0.05}};

// Fiducials on a 6 x 6 x 6 grid of 40 mm, targets at cell centres, monitors in 8 visits.
MeasurementSet cell(const RigidTransform& T_sensor_robot, Random* rng) {
  MeasurementSet set;
  set.source = "cell.csv";
  set.has_visit = true;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) {
        const Eigen::Vector3d p(0.4 + 0.04 * i, -0.1 + 0.04 * j, 0.05 + 0.04 * k);
        set.locations.push_back(reading(fmt::format("f{}{}{}", i, j, k), Role::kFiducial, p,
                                        T_sensor_robot, rng, std::nullopt));
        if (i < 5 && j < 5 && k < 5) {
          set.locations.push_back(reading(fmt::format("t{}{}{}", i, j, k), Role::kTarget,
                                          p + Eigen::Vector3d::Constant(0.02), T_sensor_robot, rng,
                                          std::nullopt));
        }
      }
  for (int v = 0; v < 8; ++v)
    for (int m = 0; m < 3; ++m)
      set.locations.push_back(reading("monitor-" + std::to_string(m + 1), Role::kMonitor,
                                      kMonitors[m], T_sensor_robot, rng, v));
  return set;
}

MeasurementSet only(const MeasurementSet& set, Role role) {
  MeasurementSet out = set;
  std::erase_if(out.locations, [role](const Location& l) { return l.role != role; });
  out.source = "today.csv";
  return out;
}

TEST(Monitoring, ABumpIsFoundAndUndoneToRounding) {
  const RigidTransform T_sensor_robot = tracker();
  const MeasurementSet set = cell(T_sensor_robot, nullptr);
  const RegistrationModel model = register_fiducials(set).model;
  ASSERT_EQ(model.monitors.size(), 24u);
  CheckOptions options;
  options.visit_sd_m = 2e-5;
  EXPECT_EQ(check_cell(model, only(set, Role::kMonitor), options).statistics.verdict,
            MonitorVerdict::kValid);

  // The tracker turns by 60 urad about a point 1 m off and shifts 50 um.
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(6e-5, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d pivot(1.0, 0.5, 1.5);
  const RigidTransform T_after_before(R, pivot - R * pivot + Eigen::Vector3d(5e-5, 0, -3e-5));
  const MeasurementSet bumped = cell(T_after_before * T_sensor_robot, nullptr);
  const CheckResult c = check_cell(model, only(bumped, Role::kMonitor), options);
  EXPECT_EQ(c.statistics.verdict, MonitorVerdict::kRigidChange) << c.statistics.message;
  ASSERT_TRUE(c.statistics.rigid);

  UpdateOptions update;
  update.parent = "cell.json";
  update.time = "2026-11-26T10:00:00Z";
  const UpdateResult u = update_model(model, only(bumped, Role::kMonitor), update);
  EXPECT_EIGEN_NEAR(u.T_registered_sensor.rotation, R.transpose(), 1e-12);
  EXPECT_EIGEN_NEAR(u.T_registered_sensor.apply(T_after_before.apply(Eigen::Vector3d(0.1, 2, 3))),
                    Eigen::Vector3d(0.1, 2, 3), 1e-12);
  EXPECT_LT(u.fit_rms_m, 1e-12);
  ASSERT_EQ(u.model.lineage.size(), 1u);
  EXPECT_EQ(u.model.lineage[0].change, "bump");
  EXPECT_EQ(u.model.lineage[0].parent, "cell.json");
  EXPECT_EQ(u.model.lineage[0].points.size(), 3u);
  // The bumped targets correct to what the unbumped ones did.
  const EvaluateResult before = evaluate(model, set);
  const EvaluateResult after = evaluate(u.model, bumped);
  const EvaluateResult stale = evaluate(model, bumped);
  EXPECT_EIGEN_NEAR(after.correction.corrected_robot_m, before.correction.corrected_robot_m, 1e-12);
  EXPECT_GT(stale.summary.cor_rms_t_m, 1e-5);
  // The model file keeps the move: correcting today's readings as arrays agrees.
  MeasuredPoints points;
  points.sensor_m = bumped.sensor_points(bumped.select(Role::kTarget));
  points.robot_m = bumped.robot_points(bumped.select(Role::kTarget));
  EXPECT_EIGEN_NEAR(correct(u.model, points).correction.corrected_robot_m,
                    before.correction.corrected_robot_m, 1e-12);
  // Checked again against the updated model, the bumped cell is valid.
  EXPECT_EQ(check_cell(u.model, only(bumped, Role::kMonitor), options).statistics.verdict,
            MonitorVerdict::kValid);
  // A second bump of the updated model: the move is fitted to the registration's frame again.
  const RigidTransform second(Eigen::AngleAxisd(-4e-5, Eigen::Vector3d::UnitY()).toRotationMatrix(),
                              Eigen::Vector3d(-2e-5, 4e-5, 1e-5));
  const MeasurementSet twice = cell(second * T_after_before * T_sensor_robot, nullptr);
  const UpdateResult u2 = update_model(u.model, only(twice, Role::kMonitor), update);
  ASSERT_EQ(u2.model.lineage.size(), 2u);
  EXPECT_EIGEN_NEAR(evaluate(u2.model, twice).correction.corrected_robot_m,
                    before.correction.corrected_robot_m, 1e-12);
}

TEST(Monitoring, AnAffineDriftIsRecoveredToRounding) {
  const RigidTransform T_sensor_robot = tracker();
  const MeasurementSet set = cell(T_sensor_robot, nullptr);
  const RegistrationModel model = register_fiducials(set).model;
  Eigen::Matrix3d A;
  A << 2e-4, 1e-5, -3e-5, 0, 1.5e-4, 2e-5, 1e-5, 0, 2.5e-4;
  const Eigen::Vector3d b(1e-5, -2e-5, 3e-5);
  MeasurementSet today = only(set, Role::kMonitor);
  for (const std::string name : {"f000", "f505", "f550", "f055", "f333", "f500", "f050"}) {
    for (const Location& l : set.locations)
      if (l.point == name) today.locations.push_back(l);
  }
  for (Location& l : today.locations) l.sensor_m += A * l.robot_m + b;
  UpdateOptions options;
  options.change = CellChange::kDrift;
  const UpdateResult u = update_model(model, today, options);
  EXPECT_EIGEN_NEAR(u.drift.leftCols<3>(), A, 1e-12);
  EXPECT_EIGEN_NEAR(u.drift.col(3), b, 1e-12);
  EXPECT_EQ(u.n_monitors, 3);
  EXPECT_EQ(u.n_fiducials, 7);
  for (std::size_t j = 0; j < model.fiducials.size(); ++j) {
    const Location& f = model.fiducials[j];
    EXPECT_EIGEN_NEAR(u.model.fiducials[j].sensor_m, f.sensor_m + A * f.robot_m + b, 1e-12);
  }
  EXPECT_EQ(u.model.monitors.size(), model.monitors.size());
  EXPECT_EQ(u.model.lineage.back().change, "drift");
}

TEST(Monitoring, NoisyChecksSayWhatChanged) {
  Random rng(11);
  const MeasurementSet set = cell(tracker(), &rng);
  const RegistrationModel model = register_fiducials(set).model;
  // The visits' scatter gives the sd, then and today apart: 3 x 3 x 7 = 63 dof each, and
  // Welch-Satterthwaite's for their sum (126 at most, when the two agree).
  const CheckResult same = check_cell(model, only(cell(tracker(), &rng), Role::kMonitor));
  EXPECT_EQ(same.noise.dof_then, 63.0);
  EXPECT_EQ(same.noise.dof_today, 63.0);
  EXPECT_GT(same.variance_dof, 63.0);
  EXPECT_LE(same.variance_dof, 126.0);
  EXPECT_NEAR(same.visit_sd_m, 2e-5, 0.4e-5);
  EXPECT_EQ(same.statistics.verdict, MonitorVerdict::kValid) << same.statistics.message;
  // One monitor point knocked by 0.3 mm.
  MeasurementSet knocked = only(cell(tracker(), &rng), Role::kMonitor);
  for (Location& l : knocked.locations)
    if (l.point == "monitor-2") l.sensor_m += Eigen::Vector3d(0, 3e-4, 0);
  const CheckResult k = check_cell(model, knocked);
  EXPECT_EQ(k.statistics.verdict, MonitorVerdict::kOutlier) << k.statistics.message;
  ASSERT_TRUE(k.statistics.outlier);
  EXPECT_EQ(k.points[static_cast<std::size_t>(*k.statistics.outlier)].point, "monitor-2");
  // The robot grows by 1e-3 about its base: not rigid; the check names fiducials to read again.
  MeasurementSet grown = only(set, Role::kMonitor);
  for (Location& l : grown.locations) {
    l.sensor_m = tracker().apply(actual(l.robot_m * 1.001)) + rng.normal3(2e-5);
  }
  const CheckResult g = check_cell(model, grown);
  EXPECT_EQ(g.statistics.verdict, MonitorVerdict::kSmoothChange) << g.statistics.message;
  EXPECT_EQ(g.remeasure.size(), 10u);
}

TEST(Monitoring, BadInputIsRefusedWithItsPlace) {
  const MeasurementSet set = cell(tracker(), nullptr);
  const RegistrationModel model = register_fiducials(set).model;
  RegistrationModel plain = model;
  plain.monitors.clear();
  // About the model, not today's file: an InputError its caller names the model's file by.
  try {
    (void)check_cell(plain, only(set, Role::kMonitor));
    FAIL() << "a model without monitor points was checked";
  } catch (const FileError& e) {
    FAIL() << "names today's file: " << e.what();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("model has no monitor points"), std::string::npos);
  }
  MeasurementSet unknown = only(set, Role::kMonitor);
  unknown.locations[4].point = "monitor-9";
  unknown.locations[4].source_line = 17;
  try {
    (void)check_cell(model, unknown);
    FAIL() << "an unknown monitor point was accepted";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("17"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("monitor-9"), std::string::npos) << e.what();
  }
  // Noise-free visits: nothing to estimate the sd from.
  EXPECT_THROW(check_cell(model, only(set, Role::kMonitor)), InputError);
  // Two points cannot fix a bump; three on a plane cannot fix a drift.
  MeasurementSet two = only(set, Role::kMonitor);
  std::erase_if(two.locations, [](const Location& l) { return l.point == "monitor-3"; });
  EXPECT_THROW(update_model(model, two, {}), FileError);
  UpdateOptions drift;
  drift.change = CellChange::kDrift;
  EXPECT_THROW(update_model(model, only(set, Role::kMonitor), drift), FileError);
}

}  // namespace
}  // namespace vrreg
