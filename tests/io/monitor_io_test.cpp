// SPDX-License-Identifier: Apache-2.0
// Monitor points in files: the measurement CSV's monitor role and visit column, a model's monitor
// points, sensor move and lineage through its JSON, and a cell's check history.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "vrreg/core/file_error.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/io/monitor_json.hpp"
#include "vrreg_test.hpp"

namespace vrreg::io {
namespace {

TEST(MonitorFiles, VisitsOfAMonitorPointStayApart) {
  std::istringstream in(
      "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm,visit\n"
      "M1,monitor,1,2,3,10,20,30,0\n"
      "M1,monitor,1,2,3,10.2,20,30,0\n"
      "M1,monitor,1,2,3,11,20,30,1\n"
      "F1,fiducial,4,5,6,40,50,60,0\n");
  const MeasurementSet set = parse_measurement_csv(in, "m.csv");
  ASSERT_EQ(set.locations.size(), 3u);
  EXPECT_TRUE(set.has_visit);
  EXPECT_EQ(set.locations[0].role, Role::kMonitor);
  EXPECT_EQ(set.locations[0].visit, 0);
  EXPECT_EQ(set.locations[0].n_readings, 2);
  EXPECT_NEAR(set.locations[0].sensor_m.x(), 0.0101, 1e-15);
  EXPECT_EQ(set.locations[1].visit, 1);
  EXPECT_EQ(set.select(Role::kMonitor).size(), 2u);

  std::istringstream bad(
      "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm,visit\n"
      "M1,monitor,1,2,3,10,20,30,-1\n");
  try {
    (void)parse_measurement_csv(bad, "bad.csv");
    FAIL() << "a negative visit was read";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:2"), std::string::npos) << e.what();
  }
}

TEST(MonitorFiles, AModelKeepsItsMonitorsMoveAndLineage) {
  RegistrationModel model;
  for (int j = 0; j < 4; ++j) {
    Location f;
    f.point = "f" + std::to_string(j);
    f.robot_m = Eigen::Vector3d(0.1 * j, 0.05 * (j % 2), 0.02 * (j / 2));
    f.sensor_m = f.robot_m + Eigen::Vector3d(1, 2, 3);
    f.n_readings = 1;
    model.fiducials.push_back(f);
  }
  model.corrections_sensor_m = Points3::Zero(3, 4);
  Location m = model.fiducials[1];
  m.point = "monitor-1";
  m.role = Role::kMonitor;
  m.visit = 3;
  m.n_readings = 12;
  model.monitors.push_back(m);
  model.T_registered_sensor =
      RigidTransform(Eigen::AngleAxisd(1e-4, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                     Eigen::Vector3d(1e-5, 2e-5, -3e-5));
  model.lineage.push_back(
      {"bump", "cell.json", "today.csv", {"monitor-1", "f2@1"}, "2026-11-26T10:00:00Z", 1.25e-5});
  const RegistrationModel back = parse_model_json(format_model_json(model), "m.json");
  ASSERT_EQ(back.monitors.size(), 1u);
  EXPECT_EQ(back.monitors[0].point, "monitor-1");
  EXPECT_EQ(back.monitors[0].role, Role::kMonitor);
  EXPECT_EQ(back.monitors[0].visit, 3);
  EXPECT_EQ(back.monitors[0].n_readings, 12);
  EXPECT_EQ(back.monitors[0].sensor_m, m.sensor_m);  // shortest round-trip text: exact
  ASSERT_TRUE(back.T_registered_sensor);
  EXPECT_EQ(back.T_registered_sensor->rotation, model.T_registered_sensor->rotation);
  EXPECT_EQ(back.T_registered_sensor->translation_m, model.T_registered_sensor->translation_m);
  ASSERT_EQ(back.lineage.size(), 1u);
  EXPECT_EQ(back.lineage[0].points, model.lineage[0].points);
  EXPECT_EQ(back.lineage[0].time, "2026-11-26T10:00:00Z");
  EXPECT_EQ(back.lineage[0].fit_rms_m, 1.25e-5);
  // A model without them writes none of the keys (older files' bytes stay).
  RegistrationModel plain = model;
  plain.monitors.clear();
  plain.T_registered_sensor.reset();
  plain.lineage.clear();
  const std::string text = format_model_json(plain);
  EXPECT_EQ(text.find("monitors"), std::string::npos);
  EXPECT_EQ(text.find("lineage"), std::string::npos);
}

TEST(MonitorFiles, AHistoryGrowsOneRowPerCheck) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("vrreg_history_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "history.csv").string();
  CheckResult r;
  r.points.resize(3);
  r.statistics.change_rms_m = 1.5e-4;
  r.statistics.verdict = MonitorVerdict::kRigidChange;
  append_check_history(path, "2026-11-26T08:00:00Z", "a.csv", r);
  r.statistics.verdict = MonitorVerdict::kValid;
  r.statistics.change_rms_m = 2e-5;
  append_check_history(path, "2026-11-26T09:00:00Z", "b.csv", r);
  const std::vector<CheckHistoryRow> rows = read_check_history(path);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].verdict, "rigid change");
  EXPECT_DOUBLE_EQ(rows[0].change_rms_mm, 0.15);
  EXPECT_EQ(rows[1].time, "2026-11-26T09:00:00Z");
  EXPECT_EQ(rows[1].monitors, 3);
  EXPECT_THROW(append_check_history(path, "a,b", "c.csv", r), FileError);
  std::ofstream(path, std::ios::app) << "2026-11-26T10:00:00Z,exploded,1,3,c.csv\n";
  try {
    (void)read_check_history(path);
    FAIL() << "an unknown verdict was read";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(":4"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::io
