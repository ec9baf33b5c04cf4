// SPDX-License-Identifier: Apache-2.0
// A cell's life on the command line: plan monitor points, register with them, check (exit 0),
// check after a bump of the tracker (exit 10), update from the monitors and a few fiducials,
// check again with the new model (exit 0); the history and the lineage record it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/io/measurement_csv_writer.hpp"
#include "vrreg/planning/spread_points.hpp"
#include "vrreg/simulation/acquisition.hpp"
#include "vrreg/simulation/cell_events.hpp"
#include "vrreg/simulation/read_locations.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

io::Reading row_of(const Location& l) {
  io::Reading r;
  r.point = l.point;
  r.role = l.role;
  r.robot_m = l.robot_m;
  r.sensor_m = l.sensor_m;
  r.visit = l.visit.value_or(0);
  return r;
}

// A simulated UR5 A1 cell with 3 monitor points; writes the registration file, today's readings
// unchanged, after a bump, and after it with 7 fiducials.
struct Files {
  std::string cell = "cell.csv", same = "same.csv", bumped = "bumped.csv", update = "update.csv";
};

Files write_cell(const fs::path& dir) {
  const simulation::Testbed bed = simulation::ur5_testbed();
  simulation::SimulationOptions sim;
  sim.seed = 3;
  const simulation::SimulatedDataset data =
      simulation::simulate_dataset(bed, simulation::Dataset::kA1, sim);
  const MeasurementSet set = experiments::to_measurement_set(data);
  const simulation::SimulatedRobot robot(bed.nominal, data.errors.robot, data.robot);
  const std::vector<std::size_t> fiducials = set.select(Role::kFiducial);
  const std::vector<std::size_t> spread = planning::spread_points(set.robot_points(fiducials), 10);
  std::vector<simulation::CommandedLocation> monitors, extra;
  for (std::size_t k = 0; k < spread.size(); ++k) {
    const Location& l = set.locations[fiducials[spread[k]]];
    const Eigen::Map<const Eigen::VectorXd> q(l.q_rad.data(),
                                              static_cast<Eigen::Index>(l.q_rad.size()));
    if (k < 3) {
      monitors.push_back({"monitor-" + std::to_string(k + 1), Role::kMonitor, l.robot_m, {}, q});
    } else {
      extra.push_back({l.point, Role::kFiducial, l.robot_m, {}, q});
    }
  }
  Random rng(17);
  const auto read = [&](const RigidTransform& T,
                        const std::vector<simulation::CommandedLocation>& where, int visits) {
    std::vector<io::Reading> rows;
    for (const Location& l :
         simulation::read_locations(robot, T, data.errors.tracker, where, visits, rng))
      rows.push_back(row_of(l));
    return rows;
  };
  Files f;
  std::vector<io::Reading> cell;
  for (const Location& l : set.locations) cell.push_back(row_of(l));
  for (const io::Reading& r : read(data.T_robot_sensor, monitors, 8)) cell.push_back(r);
  io::write_measurement_csv((dir / f.cell).string(), cell);
  io::write_measurement_csv((dir / f.same).string(), read(data.T_robot_sensor, monitors, 8));
  const RigidTransform bump =
      simulation::draw_bump(set.sensor_points(set.select(Role::kTarget)), 3e-4, rng);
  const RigidTransform moved = data.T_robot_sensor * bump.inverse();
  std::vector<io::Reading> bumped = read(moved, monitors, 8);
  io::write_measurement_csv((dir / f.bumped).string(), bumped);
  for (const io::Reading& r : read(moved, extra, 1)) bumped.push_back(r);
  io::write_measurement_csv((dir / f.update).string(), bumped);
  return f;
}

TEST(MonitorCli, RegisterCheckBumpUpdateCheck) {
  const fs::path dir = fresh_dir("monitor_cli");
  const Files f = write_cell(dir);
  ASSERT_EQ(run_vrreg_in(dir, "register --fiducials " + f.cell + " -o cell.json").status, 0);

  const CliResult same =
      run_vrreg_in(dir, "check --model cell.json --monitor " + f.same +
                            " --history history.csv --time 2026-11-26T08:00:00Z");
  EXPECT_EQ(same.status, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("valid"), std::string::npos) << same.out;

  const CliResult bumped =
      run_vrreg_in(dir, "check --model cell.json --monitor " + f.bumped +
                            " --json --history history.csv --time 2026-11-26T09:00:00Z");
  EXPECT_EQ(bumped.status, 10) << bumped.out << bumped.err;
  const nlohmann::json j = nlohmann::json::parse(bumped.out);
  EXPECT_EQ(j["verdict"], "rigid change");
  EXPECT_EQ(j["n_monitors"], 3);
  EXPECT_TRUE(j.contains("sensor_moved"));
  EXPECT_EQ(j["time"], "2026-11-26T09:00:00Z");
  EXPECT_TRUE(bumped.err.empty()) << bumped.err;

  const CliResult update =
      run_vrreg_in(dir, "update --model cell.json --points " + f.update +
                            " --change bump -o cell-2.json --time 2026-11-26T09:05:00Z --json");
  ASSERT_EQ(update.status, 0) << update.err;
  const nlohmann::json u = nlohmann::json::parse(update.out);
  EXPECT_EQ(u["change"], "bump");
  EXPECT_EQ(u["n_monitors"], 3);
  EXPECT_EQ(u["n_fiducials"], 7);
  const nlohmann::json model = nlohmann::json::parse(read_text(dir / "cell-2.json"));
  ASSERT_EQ(model["lineage"].size(), 1u);
  EXPECT_EQ(model["lineage"][0]["parent"], "cell.json");
  EXPECT_EQ(model["lineage"][0]["time"], "2026-11-26T09:05:00Z");
  EXPECT_TRUE(model.contains("T_registered_sensor"));

  const CliResult again = run_vrreg_in(dir, "check --model cell-2.json --monitor " + f.bumped);
  EXPECT_EQ(again.status, 0) << again.out << again.err;

  const std::string history = read_text(dir / "history.csv");
  EXPECT_NE(history.find("2026-11-26T08:00:00Z,valid,"), std::string::npos) << history;
  EXPECT_NE(history.find("2026-11-26T09:00:00Z,rigid change,"), std::string::npos) << history;

  // The report page draws the history, one point per check.
  const CliResult page = run_vrreg_in(
      dir, "report --model cell.json --targets " + f.cell + " --history history.csv -o r.html");
  ASSERT_EQ(page.status, 0) << page.err;
  const std::string html = read_text(dir / "r.html");
  EXPECT_NE(html.find("Monitor history"), std::string::npos);
  EXPECT_NE(html.find("rigid change"), std::string::npos);

  // Today's file with no monitor rows: a one-line error naming it, exit 1.
  write_text(dir / "fiducials.csv",
             "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm\n"
             "F1,fiducial,1,2,3,4,5,6\n");
  const CliResult none = run_vrreg_in(dir, "check --model cell.json --monitor fiducials.csv");
  EXPECT_EQ(none.status, 1);
  EXPECT_NE(none.err.find("fiducials.csv"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("no monitor rows"), std::string::npos) << none.err;
  fs::remove_all(dir);
}

TEST(MonitorCli, PlanChoosesMonitorPointsAndWritesTheCheckProgram) {
  const fs::path dir = fresh_dir("monitor_plan");
  write_text(dir / "parts.csv", "point,robot_x_mm,robot_y_mm,robot_z_mm\nP1,-400,-100,300\n");
  const CliResult r = run_vrreg_in(
      dir,
      "plan --parts parts.csv --robot ur5 --halfwidth-mm 10 --spacing-mm 10 --monitor 3 "
      "--monitor-visits 4 --export csv --program all.csv --monitor-program check.csv -o plan.csv");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string plan = read_text(dir / "plan.csv");
  EXPECT_NE(plan.find("monitor-3,monitor,"), std::string::npos) << plan;
  const std::string check = read_text(dir / "check.csv");
  int rows = 0;
  for (std::size_t at = check.find(",monitor,"); at != std::string::npos;
       at = check.find(",monitor,", at + 1))
    ++rows;
  EXPECT_EQ(rows, 12) << check;  // 3 points x 4 visits
  EXPECT_NE(check.find(",visit\n"), std::string::npos) << check;
  const CliResult no = run_vrreg_in(
      dir,
      "plan --parts parts.csv --robot ur5 --halfwidth-mm 10 --spacing-mm 10 --export csv "
      "--program a.csv --monitor-program c.csv");
  EXPECT_EQ(no.status, 1);
  EXPECT_NE(no.err.find("--monitor"), std::string::npos) << no.err;
  fs::remove_all(dir);
}

TEST(MonitorCli, SimulatedHoursLaterABumpAndAWarmUpAreTold) {
  const fs::path dir = fresh_dir("monitor_time");
  write_text(dir / "parts.csv", "point,robot_x_mm,robot_y_mm,robot_z_mm\nP1,-400,-100,300\n");
  ASSERT_EQ(run_vrreg_in(dir,
                         "plan --parts parts.csv --robot ur5 --halfwidth-mm 100 "
                         "--spacing-mm 50 --monitor 3 -o plan.csv")
                .status,
            0);
  ASSERT_EQ(run_vrreg_in(dir, "simulate ur5 --plan plan.csv --seed 5 -o cell.csv").status, 0);
  ASSERT_EQ(run_vrreg_in(dir, "register --fiducials cell.csv -o cell.json").status, 0);
  const auto check = [&](const std::string& later) {
    const CliResult s = run_vrreg_in(
        dir, "simulate ur5 --plan plan.csv --seed 5 --only monitor -o today.csv " + later);
    EXPECT_EQ(s.status, 0) << s.err;
    const CliResult c = run_vrreg_in(dir, "check --model cell.json --monitor today.csv");
    return c.status;
  };
  EXPECT_EQ(check("--at-h 2"), 0);
  EXPECT_EQ(check("--at-h 2 --bump-mm 0.3 --bump-at-h 1"), 10);
  EXPECT_EQ(check("--at-h 2 --bump-mm 0.3 --bump-at-h 3"), 0);  // not yet bumped
  EXPECT_EQ(check("--at-h 3 --warmup-growth 2e-3 --warmup-tau-h 0.5"), 11);
  const CliResult bad = run_vrreg_in(dir, "simulate ur5 A1 --only monitor -o x.csv");
  EXPECT_EQ(bad.status, 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
