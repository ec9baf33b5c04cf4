// SPDX-License-Identifier: Apache-2.0
// Robot files on the command line: the repository's URDFs as given (the UR5 with its ROS base_link
// plans; the UR5 on a rail answers `ik --current-deg` next to its current joints, the rail in mm),
// and files that are not robots refused in one line naming them, never a crash or a wait.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

const std::string kUrdfDir = std::string(VRREG_SOURCE_DIR) + "/tests/data/urdf/";

std::string numbers(const nlohmann::json& list) {
  std::string text;
  for (const auto& v : list) text += " " + nlohmann::json(v.get<double>()).dump();
  return text;
}

TEST(RobotFileCli, IkCurrentJointsOfARailRobotInTheirOwnUnits) {
  const std::string robot = shell_quoted(kUrdfDir + "ur5_on_rail.urdf");
  const std::string current = "800 30 -70 100 -120 -80 40";  // rail mm, then arm deg
  const CliResult fk = run_vrreg("fk --json " + robot + " --deg " + current);
  ASSERT_EQ(fk.status, 0) << fk.err;
  const nlohmann::json pose = nlohmann::json::parse(fk.out);
  const CliResult ik =
      run_vrreg("ik --json " + robot + " --xyz-mm" + numbers(pose["xyz_mm"]) + " --rpy-deg" +
                numbers(pose["rpy_deg"]) + " --current-deg " + current);
  ASSERT_EQ(ik.status, 0) << ik.err;
  const nlohmann::json answer = nlohmann::json::parse(ik.out);
  ASSERT_EQ(answer["solutions"].size(), 1u) << ik.out;
  const nlohmann::json& q = answer["solutions"][0]["q_deg"];
  const double want[] = {800, 30, -70, 100, -120, -80, 40};
  ASSERT_EQ(q.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) EXPECT_NEAR(q[i].get<double>(), want[i], 1e-6) << i;
}

TEST(RobotFileCli, PlanTakesTheRepositorysUr5Urdf) {
  const auto dir = fresh_dir("plan-ur5-urdf");
  write_text(dir / "parts.csv",
             "point,robot_x_mm,robot_y_mm,robot_z_mm\n"
             "hole_A,420,-140,250\nhole_B,480,-140,250\npin_C,480,-60,260\npin_D,420,-60,240\n");
  const CliResult r =
      run_vrreg("plan --parts " + shell_quoted(dir / "parts.csv") +
                " --halfwidth-mm 10 --spacing-mm 5 --robot " + shell_quoted(kUrdfDir + "ur5.urdf") +
                " -o " + shell_quoted(dir / "plan.csv"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "plan.csv"));
  std::filesystem::remove_all(dir);
}

TEST(RobotFileCli, NotARobotFileIsOneLineNamingIt) {
  const auto dir = fresh_dir("not-a-robot-file");
  std::string nested = "<robot name='r'>";
  for (int i = 0; i < 60000; ++i) nested += "<a>";
  for (int i = 0; i < 60000; ++i) nested += "</a>";
  write_text(dir / "deep.urdf", nested + "</robot>");
  std::filesystem::create_directory(dir / "folder.urdf");
  ASSERT_EQ(::mkfifo((dir / "pipe.urdf").c_str(), 0600), 0);
  const struct {
    const char* name;
    const char* fragment;
  } cases[] = {
      {"deep.urdf", "XML elements nest deeper than 256 levels"},
      {"folder.urdf", "is a directory, not a regular file"},
      {"pipe.urdf", "is a FIFO, not a regular file"},
  };
  for (const auto& c : cases) {
    const std::string path = (dir / c.name).string();
    const CliResult r = run_vrreg("fk " + shell_quoted(path) + " 0 0 0 0 0 0");
    EXPECT_EQ(r.status, 1) << c.name << ": " << r.err;
    EXPECT_TRUE(r.err.starts_with("vrreg: error: " + path + ": ")) << r.err;
    EXPECT_NE(r.err.find(c.fragment), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing
