// SPDX-License-Identifier: Apache-2.0
// Orientations on the command line: simulate a rigid-body marker, register with the joint model
// (the orientation field saved in the model), evaluate (RMS angle in the table, the JSON and the
// per-target file), correct (the corrected orientation to command in the CSV), and the same
// numbers from the saved model as from the fit; a sphere's files keep their columns.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

TEST(OrientationCli, SimulateRegisterEvaluateCorrectWithARigidBody) {
  const fs::path dir = fresh_dir("orientation_cli");
  const auto path = [&dir](const char* name) { return (dir / name).string(); };
  ASSERT_EQ(run_vrreg("simulate ur5 A1 --rigid-body-mm 50 -o " + path("a1.csv")).status, 0);
  const std::string csv = read_text(dir / "a1.csv");
  EXPECT_NE(csv.find("# rigid body: 4 spheres on a 50 mm radius"), std::string::npos);
  EXPECT_NE(
      csv.find(",sensor_qx,sensor_qy,sensor_qz,sensor_qw,robot_qx,robot_qy,robot_qz,robot_qw\n"),
      std::string::npos);
  const CliResult reg = run_vrreg("register --fiducials " + path("a1.csv") +
                                  " --robot ur5 --interpolation joint -o " + path("cell.json"));
  ASSERT_EQ(reg.status, 0) << reg.err;
  const nlohmann::json model = nlohmann::json::parse(read_text(dir / "cell.json"));
  ASSERT_TRUE(model.contains("orientation_corrector"));
  EXPECT_EQ(model["orientation_corrector"]["method"], "joint");
  // The wrist's link rotations, which positions do not show, are saved with the joint terms.
  EXPECT_EQ(model["orientation_corrector"]["joint_terms"]["link_rotations_rad"].size(), 18U);
  EXPECT_EQ(model["fiducials"][0]["q_sensor_marker"].size(), 4U);

  const CliResult table = run_vrreg("evaluate --model " + path("cell.json") + " --targets " +
                                    path("a1.csv") + " --per-target " + path("targets.csv"));
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("RMS angle (orientation)"), std::string::npos) << table.out;
  const CliResult as_json =
      run_vrreg("evaluate --json --model " + path("cell.json") + " --targets " + path("a1.csv"));
  ASSERT_EQ(as_json.status, 0) << as_json.err;
  const nlohmann::json o = nlohmann::json::parse(as_json.out)["orientation"];
  const double unc = o["unc_rms_angle_mrad"].get<double>();
  const double cor = o["cor_rms_angle_mrad"].get<double>();
  EXPECT_GT(unc, 5.0);        // the UR5's wrist offsets: ~16 mrad
  EXPECT_LT(cor, 0.2 * unc);  // >= 80 % removed
  EXPECT_LT(cor, 0.5);        // to the A1 cell's noise floor (0.36 mrad)
  EXPECT_GT(o["calibration"]["rms_angle_over_sd"].get<double>(), 0.8);
  EXPECT_LT(o["calibration"]["rms_angle_over_sd"].get<double>(), 1.25);
  EXPECT_NE(read_text(dir / "targets.csv").find(",unc_angle_mrad,cor_angle_mrad"),
            std::string::npos);

  const CliResult corrected = run_vrreg("correct --model " + path("cell.json") + " --points " +
                                        path("a1.csv") + " -o " + path("corrected.csv"));
  ASSERT_EQ(corrected.status, 0) << corrected.err;
  std::istringstream lines(read_text(dir / "corrected.csv"));
  std::string comment, header, row;
  std::getline(lines, comment);
  std::getline(lines, header);
  std::getline(lines, row);
  EXPECT_NE(header.find(",robot_qx,robot_qy,robot_qz,robot_qw,rotation_x_mrad"), std::string::npos);
  // The corrected orientation is a unit quaternion.
  std::vector<double> fields;
  std::istringstream cells(row);
  for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(std::atof(cell.c_str()));
  // after point,config,status, 3 x 3 positions, predicted_sd_mm, orientation_status
  const std::size_t qx = 14;
  EXPECT_NE(header.find(",predicted_sd_mm,orientation_status,robot_qx"), std::string::npos);
  EXPECT_NE(row.find(",ok,"), std::string::npos);
  ASSERT_GT(fields.size(), qx + 3);
  EXPECT_NEAR(Eigen::Vector4d(fields[qx], fields[qx + 1], fields[qx + 2], fields[qx + 3]).norm(),
              1.0, 1e-10);

  // Fitted now (--refit) or restored from the file: the same figures.
  const CliResult refit = run_vrreg("evaluate --json --refit --model " + path("cell.json") +
                                    " --targets " + path("a1.csv"));
  ASSERT_EQ(refit.status, 0) << refit.err;
  EXPECT_EQ(nlohmann::json::parse(refit.out)["orientation"], o);
}

TEST(OrientationCli, BadQuaternionColumnsAreOneLineErrors) {
  const fs::path dir = fresh_dir("orientation_cli_bad");
  const fs::path file = dir / "bad.csv";
  {
    std::ofstream out(file);
    out << "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm,"
           "sensor_qx,sensor_qy,sensor_qz,sensor_qw,robot_qx,robot_qy,robot_qz\n";
  }
  const CliResult r = run_vrreg("register --fiducials " + file.string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("missing column 'robot_qw'"), std::string::npos) << r.err;
  {
    std::ofstream out(file);
    out << "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm,"
           "robot_qx,robot_qy,robot_qz,robot_qw\n";
  }
  const CliResult alone = run_vrreg("register --fiducials " + file.string());
  EXPECT_NE(alone.status, 0);
  EXPECT_NE(alone.err.find("robot_qx..robot_qw without sensor_qx..sensor_qw"), std::string::npos)
      << alone.err;
}

TEST(OrientationCli, OrientationsAModelCannotCorrectAreSaidNotCorrected) {
  const fs::path dir = fresh_dir("orientation_cli_spheres");
  const auto path = [&dir](const char* name) { return (dir / name).string(); };
  ASSERT_EQ(run_vrreg("simulate ur5 A1 -o " + path("spheres.csv")).status, 0);
  ASSERT_EQ(run_vrreg("simulate ur5 A1 --rigid-body-mm 50 -o " + path("body.csv")).status, 0);
  ASSERT_EQ(
      run_vrreg("register --fiducials " + path("spheres.csv") + " -o " + path("m.json")).status, 0);
  const CliResult r = run_vrreg("correct --model " + path("m.json") + " --points " +
                                path("body.csv") + " -o " + path("out.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("orientations (sensor_q*) are not corrected"), std::string::npos) << r.err;
  EXPECT_EQ(read_text(dir / "out.csv").find("robot_qx"), std::string::npos);
  // Points without orientations: nothing to say.
  const CliResult plain = run_vrreg("correct --model " + path("m.json") + " --points " +
                                    path("spheres.csv") + " -o " + path("out2.csv"));
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(plain.err.find("not corrected"), std::string::npos) << plain.err;
}

TEST(OrientationCli, SnippetsWriteThePoseFunctions) {
  const fs::path dir = fresh_dir("orientation_cli_snippet");
  const auto path = [&dir](const char* name) { return (dir / name).string(); };
  const CliResult krl =
      run_vrreg("snippet krl --pose --model cell --connect 10.0.0.2:30401 -o " +
                path("VRREG_CORRECT_POSE.src") + " --eki-config " + path("vrreg.xml"));
  ASSERT_EQ(krl.status, 0) << krl.err;
  const std::string program = read_text(dir / "VRREG_CORRECT_POSE.src");
  EXPECT_NE(program.find("DEFFCT BOOL VRREG_CORRECT_POSE("), std::string::npos);
  EXPECT_NE(program.find("abc %.6f %.6f %.6f"), std::string::npos);
  EXPECT_NE(read_text(dir / "vrreg.xml").find("<IP>10.0.0.2</IP>"), std::string::npos);
  const CliResult ur = run_vrreg("snippet urscript --model cell -o " + path("vrreg.script"));
  ASSERT_EQ(ur.status, 0) << ur.err;
  EXPECT_NE(read_text(dir / "vrreg.script").find("def vrreg_correct_pose(p_sensor_mm):"),
            std::string::npos);
  const CliResult wrong = run_vrreg("snippet urscript --pose --model cell -o " + path("x.script"));
  EXPECT_NE(wrong.status, 0);
  EXPECT_NE(wrong.err.find("--pose: for krl only"), std::string::npos) << wrong.err;
  EXPECT_FALSE(fs::exists(dir / "x.script"));
}

}  // namespace
}  // namespace vrreg::testing
