// SPDX-License-Identifier: Apache-2.0
// check_cell and update_model under what a plant meets, by Monte Carlo on a cell made here
// (fiducials on a grid, the tracker 2 m away, 4 monitor points off one plane): a noisier,
// shorter check; fewer than 3 monitors read; a warm-up and a bump told by the checks before them;
// a stretch along the normal of 3 monitors' plane; an update on a day nothing changed.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <functional>

#include "vrreg/core/file_error.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/vrreg.hpp"
#include "vrreg_test.hpp"

namespace vrreg::check_cases_test {
namespace {

constexpr double kVisitSdM = 2e-5;  // one visit's mean per axis

RigidTransform tracker_pose() {
  return RigidTransform(
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 1.0, -0.3).normalized()).toRotationMatrix(),
      Eigen::Vector3d(0.3, -0.2, 2.0));
}

// Where the robot really goes for command p [m]: a smooth field of ~0.3 mm, its links grown by
// `growth` about its base, and `knock` added.
struct RobotState {
  double growth = 0.0;
  Eigen::Matrix3d knock = Eigen::Matrix3d::Zero();  // an affine change d = K (p - centre)
  Eigen::Vector3d knock_centre = Eigen::Vector3d::Zero();
};

Eigen::Vector3d reached(const Eigen::Vector3d& p, const RobotState& s) {
  return (1.0 + s.growth) * p +
         3e-4 * Eigen::Vector3d(std::sin(9 * p.x()), std::cos(7 * p.y()), std::sin(5 * p.z())) +
         s.knock * (p - s.knock_centre);
}

const std::vector<Eigen::Vector3d> kFourMonitors = {
    {0.40, -0.10, 0.05}, {0.60, 0.10, 0.05}, {0.40, 0.10, 0.25}, {0.60, -0.10, 0.25}};

Location monitor_reading(int m, const Eigen::Vector3d& robot_m, const RigidTransform& T,
                         const RobotState& s, Random& rng, double sd_m, int visit) {
  Location l;
  l.point = "monitor-" + std::to_string(m + 1);
  l.role = Role::kMonitor;
  l.visit = visit;
  l.robot_m = robot_m;
  l.sensor_m = T.apply(reached(robot_m, s)) + rng.normal3(sd_m);
  l.n_readings = 1;
  return l;
}

// The cell at registration: 6 x 6 x 6 fiducials of 40 mm from (0.4, -0.1, 0.05) m, the monitors
// in 12 visits.
MeasurementSet registered_cell(Random& rng, const std::vector<Eigen::Vector3d>& monitors) {
  MeasurementSet set;
  set.source = "cell.csv";
  set.has_visit = true;
  const Points3 grid = testing::cube_grid_m(6, 0.04).colwise() + Eigen::Vector3d(0.1, 0.0, -0.05);
  for (Eigen::Index j = 0; j < grid.cols(); ++j) {
    Location f;
    f.point = fmt::format("f{}{}{}", j % 6, j / 6 % 6, j / 36);
    f.robot_m = grid.col(j);
    f.sensor_m = tracker_pose().apply(reached(f.robot_m, {})) + rng.normal3(kVisitSdM);
    f.n_readings = 1;
    set.locations.push_back(f);
  }
  for (int v = 0; v < 12; ++v)
    for (std::size_t m = 0; m < monitors.size(); ++m)
      set.locations.push_back(
          monitor_reading(static_cast<int>(m), monitors[m], tracker_pose(), {}, rng, kVisitSdM, v));
  return set;
}

// Today's monitor rows: `visits` visits of the first `count` monitors at `sd_m`.
MeasurementSet monitors_today(Random& rng, const std::vector<Eigen::Vector3d>& monitors,
                              std::size_t count, int visits, double sd_m,
                              const RigidTransform& T = tracker_pose(), const RobotState& s = {}) {
  MeasurementSet set;
  set.source = "today.csv";
  set.has_visit = true;
  for (int v = 0; v < visits; ++v)
    for (std::size_t m = 0; m < count; ++m)
      set.locations.push_back(
          monitor_reading(static_cast<int>(m), monitors[m], T, s, rng, sd_m, v));
  return set;
}

double three_sd(double rate, int runs) { return 3.0 * std::sqrt(rate * (1.0 - rate) / runs); }

TEST(CheckCases, AShorterNoisierCheckIsNoisierNotABump) {
  Random rng(61);
  const RegistrationModel model = register_fiducials(registered_cell(rng, kFourMonitors)).model;
  const int days = testing::sanitized() ? 100 : 600;
  int changed_noisy = 0, noisier = 0, alarms_same = 0;
  for (int d = 0; d < days; ++d) {
    // 4 visits at twice the registration's noise, nothing changed.
    const CheckResult c =
        check_cell(model, monitors_today(rng, kFourMonitors, 4, 4, 2 * kVisitSdM));
    const MonitorVerdict v = c.statistics.verdict;
    noisier += v == MonitorVerdict::kNoisier ? 1 : 0;
    changed_noisy += v != MonitorVerdict::kValid && v != MonitorVerdict::kNoisier ? 1 : 0;
    // The same noise: every kind of alarm together at the stated rate.
    alarms_same +=
        check_cell(model, monitors_today(rng, kFourMonitors, 4, 4, kVisitSdM)).statistics.verdict !=
                MonitorVerdict::kValid
            ? 1
            : 0;
  }
  const auto rate = [days](int k) { return static_cast<double>(k) / days; };
  std::printf(
      "unchanged days, 4 visits: twice the noise: called changed %.4f, noisier today "
      "%.3f; the same noise: not valid %.4f (stated 0.01)\n",
      rate(changed_noisy), rate(noisier), rate(alarms_same));
  EXPECT_LE(rate(changed_noisy), 0.01 + three_sd(0.01, days));
  EXPECT_GT(rate(noisier), 0.9);
  EXPECT_NEAR(rate(alarms_same), 0.01, three_sd(0.01, days));
  // A bump on a noisy day is still a bump, and says the day was noisier.
  RigidTransform moved = tracker_pose();
  moved.translation_m += Eigen::Vector3d(2e-4, 0, 0);
  const CheckResult bumped =
      check_cell(model, monitors_today(rng, kFourMonitors, 4, 4, 2 * kVisitSdM, moved));
  EXPECT_EQ(bumped.statistics.verdict, MonitorVerdict::kRigidChange) << bumped.statistics.message;
  EXPECT_TRUE(bumped.noise.noisier);
  EXPECT_NEAR(bumped.today_visit_sd_m, 2 * kVisitSdM, 0.8 * kVisitSdM);
}

TEST(CheckCases, ATranslationSeenFromOneOrTwoMonitorsIsABump) {
  Random rng(67);
  const RegistrationModel model = register_fiducials(registered_cell(rng, kFourMonitors)).model;
  RigidTransform moved = tracker_pose();
  const int runs = testing::sanitized() ? 20 : 100;
  for (const std::size_t n : {1u, 2u}) {
    int rigid = 0;
    CheckResult last;
    for (int r = 0; r < runs; ++r) {
      moved.translation_m = tracker_pose().translation_m + 1e-4 * rng.normal3(1.0).normalized();
      last = check_cell(model, monitors_today(rng, kFourMonitors, n, 8, kVisitSdM, moved));
      rigid += last.statistics.verdict == MonitorVerdict::kRigidChange ? 1 : 0;
    }
    std::printf("%zu monitor point(s) read, a 0.1 mm translation: rigid change %d of %d\n", n,
                rigid, runs);
    EXPECT_GE(rigid, runs - 2);
    // It says what it cannot tell, and which fiducials to read with the monitors for an update.
    EXPECT_FALSE(last.statistics.blind_spots.empty());
    EXPECT_EQ(last.remeasure.size(), 10u);
  }
}

// Checks every 2 min, each with the history of the checks before it (when `history`): the
// verdict of the first alarm from `from_s` on.
MonitorVerdict first_alarm(const RegistrationModel& model, Random& rng,
                           const std::function<RigidTransform(double)>& tracker_at,
                           const std::function<RobotState(double)>& robot_at, bool history,
                           double from_s = 0.0) {
  CheckOptions options;
  options.visit_sd_m = kVisitSdM;
  for (int k = 1; k <= 60; ++k) {
    const double t = 120.0 * k;
    options.time_s = t;
    const CheckResult c = check_cell(
        model, monitors_today(rng, kFourMonitors, 4, 8, kVisitSdM, tracker_at(t), robot_at(t)),
        options);
    if (c.statistics.verdict != MonitorVerdict::kValid && t >= from_s) {
      return c.statistics.verdict;
    }
    const bool changed = c.statistics.verdict != MonitorVerdict::kValid &&
                         c.statistics.verdict != MonitorVerdict::kNoisier;
    if (history) options.earlier.push_back({fmt::format("t{}", t), t, c.points, changed});
  }
  return MonitorVerdict::kValid;
}

TEST(CheckCases, TheHistoryTellsAWarmUpFromABump) {
  Random rng(71);
  const RegistrationModel model = register_fiducials(registered_cell(rng, kFourMonitors)).model;
  const int cells = testing::sanitized() ? 10 : 60;
  // A warm-up: links grow by 1e-4 (1 - exp(-t / 30 min)): about 0.05 mm at the monitors.
  const auto warm = [](double t) { return RobotState{-1e-4 * std::expm1(-t / 1800.0)}; };
  const auto still = [](double) { return RobotState{}; };
  const auto fixed = [](double) { return tracker_pose(); };
  // A bump of the tracker at 13 min: 0.05 mm.
  const auto bumped = [](double t) {
    RigidTransform T = tracker_pose();
    if (t > 780.0) T.translation_m += Eigen::Vector3d(3e-5, -3e-5, 2e-5);
    return T;
  };
  int warm_drift = 0, warm_drift_alone = 0, bump_rigid = 0;
  for (int c = 0; c < cells; ++c) {
    warm_drift += first_alarm(model, rng, fixed, warm, true) == MonitorVerdict::kSmoothChange;
    warm_drift_alone +=
        first_alarm(model, rng, fixed, warm, false) == MonitorVerdict::kSmoothChange;
    bump_rigid +=
        first_alarm(model, rng, bumped, still, true, 780.0) == MonitorVerdict::kRigidChange;
  }
  std::printf(
      "first alarm, checks every 2 min: a warm-up called a drift %d of %d with the "
      "history, %d without it; a bump called a bump %d of %d\n",
      warm_drift, cells, warm_drift_alone, bump_rigid, cells);
  EXPECT_GT(warm_drift, warm_drift_alone + cells / 4);
  EXPECT_GE(bump_rigid, cells - std::max(2, cells / 20));
}

TEST(CheckCases, ThreeMonitorsMissAStretchAlongTheirNormalAndFourSeeIt) {
  Random rng(73);
  const RegistrationModel model = register_fiducials(registered_cell(rng, kFourMonitors)).model;
  // The first three monitors' plane; a change along its normal, zero on it.
  const Eigen::Vector3d n =
      (kFourMonitors[1] - kFourMonitors[0]).cross(kFourMonitors[2] - kFourMonitors[0]).normalized();
  const int knocks = testing::sanitized() ? 20 : 100;
  int seen3 = 0, seen4 = 0;
  for (int k = 0; k < knocks; ++k) {
    RobotState s;
    s.knock = rng.uniform(1.0, 2.0) * (rng.uniform() < 0.5 ? -1e-3 : 1e-3) * n * n.transpose();
    s.knock_centre = kFourMonitors[0];
    const auto today = [&](std::size_t count) {
      return monitors_today(rng, kFourMonitors, count, 8, kVisitSdM, tracker_pose(), s);
    };
    seen3 += check_cell(model, today(3)).statistics.verdict != MonitorVerdict::kValid ? 1 : 0;
    seen4 += check_cell(model, today(4)).statistics.verdict != MonitorVerdict::kValid ? 1 : 0;
  }
  std::printf(
      "a stretch along the normal of 3 monitors' plane (0.1-0.3 mm at the 4th): seen by "
      "3 monitors %d, by 4 %d of %d\n",
      seen3, seen4, knocks);
  EXPECT_LE(seen3, std::max(3, knocks / 20));  // only false alarms
  EXPECT_EQ(seen4, knocks);
}

TEST(CheckCases, AnUpdateOnAnUnchangedDayIsRefused) {
  Random rng(79);
  const RegistrationModel model = register_fiducials(registered_cell(rng, kFourMonitors)).model;
  MeasurementSet same = monitors_today(rng, kFourMonitors, 4, 8, kVisitSdM);
  for (const std::string name : {"f000", "f505", "f550", "f055", "f333", "f500"}) {
    Location f;
    f.point = name;
    f.robot_m = Eigen::Vector3d(0.4 + 0.04 * (name[1] - '0'), -0.1 + 0.04 * (name[2] - '0'),
                                0.05 + 0.04 * (name[3] - '0'));
    f.sensor_m = tracker_pose().apply(reached(f.robot_m, {})) + rng.normal3(kVisitSdM);
    f.n_readings = 1;
    same.locations.push_back(f);
  }
  for (const CellChange change : {CellChange::kBump, CellChange::kDrift}) {
    UpdateOptions options;
    options.change = change;
    try {
      (void)update_model(model, same, options);
      FAIL() << "an update on an unchanged day went ahead";
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find("no change"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("today.csv"), std::string::npos) << e.what();
    }
    options.even_if_unchanged = true;
    const UpdateResult forced = update_model(model, same, options);
    ASSERT_TRUE(forced.today_check);
    EXPECT_EQ(forced.today_check->statistics.verdict, MonitorVerdict::kValid);
  }
  // Without monitor rows to check, the history's last verdict decides.
  MeasurementSet fiducials_only = same;
  std::erase_if(fiducials_only.locations,
                [](const Location& l) { return l.role == Role::kMonitor; });
  UpdateOptions options;
  options.last_verdict = MonitorVerdict::kValid;
  EXPECT_THROW(update_model(model, fiducials_only, options), FileError);
  options.last_verdict = MonitorVerdict::kRigidChange;
  EXPECT_NO_THROW(update_model(model, fiducials_only, options));
  // A changed day goes ahead and says what the check found.
  RigidTransform moved = tracker_pose();
  moved.translation_m += Eigen::Vector3d(1e-4, 0, 0);
  const UpdateResult u =
      update_model(model, monitors_today(rng, kFourMonitors, 4, 8, kVisitSdM, moved), {});
  ASSERT_TRUE(u.today_check);
  EXPECT_EQ(u.today_check->statistics.verdict, MonitorVerdict::kRigidChange);
}

TEST(CheckCases, EarlierChecksNeedTodaysTimeAndAModelWithoutMonitorsIsTheModels) {
  Random rng(83);
  const RegistrationModel model = register_fiducials(registered_cell(rng, kFourMonitors)).model;
  CheckOptions options;
  options.earlier.push_back({"t", 1.0, {}});
  EXPECT_THROW(check_cell(model, monitors_today(rng, kFourMonitors, 4, 4, kVisitSdM), options),
               InputError);
  EXPECT_EQ(monitor_baseline_id(model), monitor_baseline_id(model));
  RegistrationModel updated = model;
  updated.lineage.push_back({});
  EXPECT_NE(monitor_baseline_id(updated), monitor_baseline_id(model));
}

}  // namespace
}  // namespace vrreg::check_cases_test
