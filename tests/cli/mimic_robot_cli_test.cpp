// SPDX-License-Identifier: Apache-2.0
// A robot with mimic joints and two equally deep leaves on the command line
// (tests/data/urdf/lift_arm.urdf: a lifting column whose stages mimic a side-branch drive, under
// a 6-axis arm): --tip-link on fk, ik, plan and register; the refusals say how to name the tip;
// the joint-space model registered on a simulated cell of it corrects the targets, and the saved
// model remembers the tip when the URDF is named again.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "coupled_cell.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/robot_io/urdf_robot.hpp"

namespace vrreg::testing::mimic_cli {
namespace {

namespace fs = std::filesystem;

std::string lift_arm() { return std::string(VRREG_TEST_DATA_DIR) + "/urdf/lift_arm.urdf"; }

bool one_line(const std::string& err) { return !err.empty() && err.find('\n') == err.size() - 1; }

TEST(MimicRobotCli, TheTipMustBeNamedAndTheErrorSaysHow) {
  const CliResult r = run_vrreg("fk " + lift_arm() + " 300 0 -90 90 0 90 0 --deg");
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(one_line(r.err)) << r.err;
  EXPECT_NE(r.err.find("lift_arm.urdf: several leaf links end 8 moving joints from the root "
                       "(camera_link, tool0): name the tip link (--tip-link NAME"),
            std::string::npos)
      << r.err;
  const CliResult builtin = run_vrreg("fk ur5 0 0 0 0 0 0 --tip-link tool0");
  EXPECT_NE(builtin.status, 0);
  EXPECT_TRUE(one_line(builtin.err)) << builtin.err;
  EXPECT_NE(builtin.err.find("tip link 'tool0' given, but the robot is the built-in ur5"),
            std::string::npos)
      << builtin.err;
  const CliResult unknown = run_vrreg("fk " + lift_arm() + " 300 0 0 0 0 0 0 --deg --tip-link x");
  EXPECT_NE(unknown.status, 0);
  EXPECT_NE(unknown.err.find("tip link 'x' is not in the URDF"), std::string::npos) << unknown.err;
  // Seven commanded joints, not eight rows.
  const CliResult eight =
      run_vrreg("fk " + lift_arm() + " 150 150 0 -90 90 0 90 0 --deg --tip-link tool0");
  EXPECT_NE(eight.status, 0);
  EXPECT_NE(eight.err.find("has 7 joints, got 8 joint values"), std::string::npos) << eight.err;
}

TEST(MimicRobotCli, ForwardAndInverseKinematicsOnTheCommandedJoints) {
  const CliResult fk =
      run_vrreg("fk " + lift_arm() + " 300 20 -80 100 -110 -90 10 --deg --tip-link tool0 --json");
  ASSERT_EQ(fk.status, 0) << fk.err;
  const nlohmann::json j = nlohmann::json::parse(fk.out);
  ASSERT_EQ(j["q_rad"].size(), 7u);
  EXPECT_EQ(j["joint_names"][0], "lift_drive");
  EXPECT_DOUBLE_EQ(j["q_deg"][0].get<double>(), 300.0);  // the drive in mm
  EXPECT_TRUE(j["within_limits"].get<bool>());
  // The library's FK of the same chain.
  const kinematics::SerialChain chain = io::read_urdf_robot(lift_arm(), {"", "tool0"});
  kinematics::JointVector q(7);
  for (int i = 0; i < 7; ++i) q(i) = j["q_rad"][static_cast<std::size_t>(i)].get<double>();
  const Eigen::Vector3d p = kinematics::forward_kinematics(chain, q).translation();
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(j["xyz_mm"][static_cast<std::size_t>(a)].get<double>(), 1e3 * p(a), 1e-9);
  }
  // Back to joints from joints 0.5 deg (and 5 mm) away: a solution reaching the pose on the
  // same branch (the lift makes the arm redundant: a curve of joints reaches it).
  const std::string xyz = std::to_string(j["xyz_mm"][0].get<double>()) + " " +
                          std::to_string(j["xyz_mm"][1].get<double>()) + " " +
                          std::to_string(j["xyz_mm"][2].get<double>());
  std::string rotation;
  for (const auto& row : j["rotation"]) {
    for (const auto& v : row) rotation += " " + nlohmann::json(v.get<double>()).dump();
  }
  const CliResult ik =
      run_vrreg("ik " + lift_arm() + " --tip-link tool0 --xyz-mm " + xyz + " --rotation" +
                rotation + " --current-deg 305 20.5 -80.5 100.5 -110.5 -90.5 10.5 --json");
  ASSERT_EQ(ik.status, 0) << ik.err << ik.out;
  const nlohmann::json k = nlohmann::json::parse(ik.out);
  ASSERT_EQ(k["solutions"].size(), 1u);
  kinematics::JointVector found(7);
  for (int i = 0; i < 7; ++i) {
    found(i) = k["solutions"][0]["q_rad"][static_cast<std::size_t>(i)].get<double>();
  }
  EXPECT_LT((found - q).cwiseAbs().maxCoeff(), 0.05);
  const Eigen::Isometry3d reached = kinematics::forward_kinematics(chain, found);
  const Eigen::Isometry3d target = kinematics::forward_kinematics(chain, q);
  EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-8);  // the printed digits
  EXPECT_LT((reached.linear() - target.linear()).cwiseAbs().maxCoeff(), 1e-8);
}

// The joint-space model on a simulated cell of the mimic robot, registered through the command
// line; the model remembers its tip (named again, the URDF needs no --tip-link).
TEST(MimicRobotCli, JointModelRegisteredOnACellRemembersTheTip) {
  const fs::path dir = fresh_dir("mimic_cell");
  const kinematics::SerialChain chain = io::read_urdf_robot(lift_arm(), {"", "tool0"});
  Random rng(41);
  const CoupledCellRobot robot = as_built(chain, rng);
  kinematics::JointVector home(7), half(7);
  home << 0.4, 0.3, -1.2, 1.5, -1.8, -1.57, 0.2;
  half << 0.35, 0.6, 0.4, 0.4, 0.6, 0.6, 0.8;
  Eigen::Isometry3d T_sensor_robot = Eigen::Isometry3d::Identity();
  T_sensor_robot.linear() =
      Eigen::AngleAxisd(0.5, Eigen::Vector3d(0.2, 0.3, 1).normalized()).toRotationMatrix();
  T_sensor_robot.translation() << 2.0, -0.5, 0.3;
  const auto fiducials = coupled_cell(chain, robot, home, half, 150, T_sensor_robot, 20e-6, rng);
  const auto targets = coupled_cell(chain, robot, home, half, 40, T_sensor_robot, 20e-6, rng);
  write_coupled_cell_csv((dir / "cell.csv").string(), fiducials, targets);

  const CliResult reg = run_vrreg_in(dir, "register --fiducials cell.csv --robot " + lift_arm() +
                                              " --tip-link tool0 --interpolation joint -o m.json");
  ASSERT_EQ(reg.status, 0) << reg.err;
  const nlohmann::json model = nlohmann::json::parse(read_text(dir / "m.json"));
  EXPECT_EQ(model["robot"]["urdf_tip_link"], "tool0");
  EXPECT_EQ(model["robot"]["joint_couplings"].size(), 8u);
  EXPECT_EQ(model["robot"]["joint_variables"].size(), 7u);
  EXPECT_EQ(model["robot"]["joint_variables"][0]["name"], "lift_drive");

  nlohmann::json first;
  for (const std::string& robot_args :
       {std::string(), " --robot " + lift_arm(), " --robot " + lift_arm() + " --tip-link tool0"}) {
    const CliResult e =
        run_vrreg_in(dir, "evaluate --model m.json --targets cell.csv --json" + robot_args);
    ASSERT_EQ(e.status, 0) << robot_args << ": " << e.err;
    const nlohmann::json j = nlohmann::json::parse(e.out);
    EXPECT_EQ(j["interpolation"], "joint");
    EXPECT_EQ(j["n_targets"], 40);
    // Uncorrected 0.39 mm; corrected 0.045 mm, near the targets' own 0.035 mm reading noise.
    EXPECT_GT(j["unc_rms_t_mm"].get<double>(), 0.3) << robot_args;
    EXPECT_LT(j["cor_rms_t_mm"].get<double>(), 0.06) << robot_args;
    if (first.is_null()) {
      first = j;
    } else {
      EXPECT_EQ(j["cor_rms_t_mm"], first["cor_rms_t_mm"]) << robot_args;
    }
  }
  // A coupling broken in the saved model: refused naming the file and the robot.
  std::string text = read_text(dir / "m.json");
  const std::string multiplier = "\"multiplier\": 0.5";
  ASSERT_NE(text.find(multiplier), std::string::npos);
  text.replace(text.find(multiplier), multiplier.size(), "\"multiplier\": 0.0");
  write_text(dir / "broken.json", text);
  const CliResult broken =
      run_vrreg_in(dir, "evaluate --model broken.json --targets cell.csv --json");
  EXPECT_NE(broken.status, 0);
  EXPECT_TRUE(one_line(broken.err)) << broken.err;
  EXPECT_NE(broken.err.find("broken.json"), std::string::npos) << broken.err;
  EXPECT_NE(broken.err.find("follows joint 'lift_drive' with multiplier 0"), std::string::npos)
      << broken.err;
  // The camera hangs on the same last link: the same arm to the joint model, which estimates
  // the marker on the flange from the fiducials.
  const CliResult other = run_vrreg_in(dir, "evaluate --model m.json --targets cell.csv --robot " +
                                                lift_arm() + " --tip-link camera_link --json");
  ASSERT_EQ(other.status, 0) << other.err;
  EXPECT_NEAR(nlohmann::json::parse(other.out)["cor_rms_t_mm"].get<double>(),
              first["cor_rms_t_mm"].get<double>(), 1e-6);
  fs::remove_all(dir);
}

// plan loads the chain to the tip named; its arm configurations need an analytic IK, which a
// chain with a lifting column (like any other generic chain) has not: refused as such.
TEST(MimicRobotCli, PlanTakesTheTipLink) {
  const fs::path dir = fresh_dir("mimic_plan");
  {
    std::ofstream parts(dir / "parts.csv");
    parts << "point,robot_x_mm,robot_y_mm,robot_z_mm\np1,1005,-605,2300\n";
  }
  const std::string plan = "plan --parts parts.csv --halfwidth-mm 20 --spacing-mm 20 --robot " +
                           lift_arm() + " --sigma-noise-mm 0.05 -o plan.csv";
  const CliResult tipped = run_vrreg_in(dir, plan + " --tip-link tool0");
  EXPECT_NE(tipped.status, 0);
  EXPECT_TRUE(one_line(tipped.err)) << tipped.err;
  EXPECT_NE(tipped.err.find("robot 'lift_arm' has neither the UR nor the LWR 4+ structure"),
            std::string::npos)
      << tipped.err;
  const CliResult untipped = run_vrreg_in(dir, plan);
  EXPECT_NE(untipped.status, 0);
  EXPECT_NE(untipped.err.find("name the tip link (--tip-link NAME"), std::string::npos)
      << untipped.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vrreg::testing::mimic_cli
