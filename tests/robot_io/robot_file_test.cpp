// SPDX-License-Identifier: Apache-2.0
#include "vrreg/robot_io/robot_file.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "io_test_helpers.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"

namespace vrreg::io {
namespace {

using units::kPi;
using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;

const char* kUr5Yaml = R"(# UR5 with a calibrated joint-2 offset and a sphere on the flange
name: ur5-cell
family: ur
dh:
  - {a_m: 0, alpha_deg: 90, d_m: 0.089159}
  - {a_mm: -425, alpha_rad: 0, d_m: 0, theta_offset_deg: 0.05}
  - {a_m: -0.39225, alpha_deg: 0, d_m: 0}
  - {a_m: 0, alpha_deg: 90, d_m: 0.10915}
  - {a_m: 0, alpha_deg: -90, d_m: 0.09465}
  - {a_m: 0, alpha_deg: 0, d_m: 0.0823}
joint_limits_deg:
  - [-360, 360]
  - [-360, 360]
  - [-180, 180]
  - [-360, 360]
  - [-360, 360]
  - [-360, 360]
tool:
  xyz_mm: [0, 0, 45.5]
)";

TEST(RobotFile, ReadsYaml) {
  TempDir dir;
  const auto chain = read_robot_file(dir.write("ur5.yaml", kUr5Yaml));
  EXPECT_EQ(chain.name(), "ur5-cell");
  EXPECT_EQ(chain.family(), kinematics::ChainFamily::kUr);
  ASSERT_EQ(chain.n_joints(), 6);
  EXPECT_DOUBLE_EQ(chain.row(1).a_m, -0.425);
  EXPECT_DOUBLE_EQ(chain.row(0).alpha_rad, kPi / 2);
  EXPECT_DOUBLE_EQ(chain.row(1).theta_offset_rad, 0.05 * kPi / 180);
  EXPECT_DOUBLE_EQ(chain.limit(2).upper_rad, kPi);
  EXPECT_DOUBLE_EQ(chain.T_flange_tcp().translation().z(), 0.0455);
}

TEST(RobotFile, ReadsJsonAndMatchesTheBuiltin) {
  TempDir dir;
  const std::string text = R"({"format": "vrreg-robot", "dh": [
    {"a_m": 0, "alpha_deg": 90, "d_m": 0.31}, {"a_m": 0, "alpha_deg": -90, "d_m": 0},
    {"a_m": 0, "alpha_deg": -90, "d_m": 0.40}, {"a_m": 0, "alpha_deg": 90, "d_m": 0},
    {"a_m": 0, "alpha_deg": 90, "d_m": 0.39}, {"a_m": 0, "alpha_deg": -90, "d_m": 0},
    {"a_m": 0, "alpha_deg": 0, "d_m": 0.078}],
    "joint_limits_deg": [[-170, 170], [-120, 120], [-170, 170], [-120, 120], [-170, 170],
                         [-120, 120], [-170, 170]],
    "base": {"xyz_m": [0, 0, 0], "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}})";
  const auto chain = read_robot_file(dir.write("my_lwr.json", text));
  EXPECT_EQ(chain.name(), "my_lwr");
  EXPECT_EQ(chain.family(), kinematics::ChainFamily::kLwr);
  const auto builtin = kinematics::lwr4();
  Eigen::VectorXd q(7);
  q << 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7;
  EXPECT_LE((kinematics::forward_kinematics(chain, q).matrix() -
             kinematics::forward_kinematics(builtin, q).matrix())
                .cwiseAbs()
                .maxCoeff(),
            1e-15);
  for (int i = 0; i < 7; ++i)
    EXPECT_NEAR(chain.limit(i).upper_rad, builtin.limit(i).upper_rad, 1e-15);
}

TEST(RobotFile, LoadRobotTakesNamesThenFiles) {
  EXPECT_EQ(load_robot("ur10").name(), "ur10");
  EXPECT_EQ(load_robot("lwr4").n_joints(), 7);
  try {
    load_robot("ur99");
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown robot 'ur99'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("ur5e"), std::string::npos) << e.what();
  }
  TempDir dir;
  EXPECT_EQ(load_robot(dir.write("r.yml", kUr5Yaml)).name(), "ur5-cell");
}

TEST(RobotFile, ErrorsNameFileLineAndKey) {
  TempDir dir;
  const auto check = [&](const std::string& name, const std::string& text, std::size_t line,
                         const std::string& fragment) {
    const std::string path = dir.write(name, text);
    EXPECT_TRUE(throws_file_error([&] { read_robot_file(path); }, path, line, fragment));
  };
  check("empty.yaml", "\n  \n", 0, "empty robot file");
  check("syntax.json", "{\"dh\": [\n  {\"a_m\": 0,,}\n]}", 2, "invalid JSON");
  check("syntax.yaml", "dh:\n  - {a_m: 0\n  - [\n", 3, "invalid YAML");
  check("nodh.yaml", "name: x\n", 1, "missing \"dh\"");
  check("missing.yaml", "dh:\n  - {a_m: 0, alpha_deg: 90}\n", 2, "dh[0]: missing d_m or d_mm");
  check("unit.yaml", "dh:\n  - {a_m: 0, alpha: 90, d_m: 0.1}\n", 2, "dh[0].alpha: unknown key");
  check("both.yaml", "dh:\n  - {a_m: 0, a_mm: 0, alpha_deg: 90, d_m: 0.1}\n", 2,
        "give either a_m or a_mm");
  check("text.yaml", "dh:\n  - a_m: 0\n    alpha_deg: ninety\n    d_m: 0.1\n", 3,
        "dh[0].alpha_deg: expected a number, got \"ninety\"");
  check("nan.yaml", "dh:\n  - {a_m: .nan, alpha_deg: 90, d_m: 0.1}\n", 2, "not a finite number");
  check("limits.yaml",
        "dh:\n  - {a_m: 0, alpha_deg: 90, d_m: 0.1}\njoint_limits_deg:\n  - [10, -10]\n", 4,
        "lower limit must be below upper limit");
  check("limits_count.json", R"({"dh": [{"a_m": 0, "alpha_deg": 90, "d_m": 0.1}],
    "joint_limits_rad": [[-1, 1], [-1, 1]]})",
        0, "expected 1 [lower, upper] pairs");
  check("rotation.yaml",
        "dh:\n  - {a_m: 0, alpha_deg: 90, d_m: 0.1}\ntool:\n  rotation: [[1, 0, 0], [0, 2, 0], "
        "[0, 0, 1]]\n",
        4, "tool.rotation: not a rotation matrix");
  check("reflection.yaml",
        "dh:\n  - {a_m: 0, alpha_deg: 90, d_m: 0.1}\nbase:\n  rotation: [[1, 0, 0], [0, 1, 0], "
        "[0, 0, -1]]\n",
        4, "not a rotation matrix");
  check("family.yaml", "family: ur\ndh:\n  - {a_m: 0, alpha_deg: 90, d_m: 0.1}\n", 1,
        "declared \"ur\" but the DH table has the structure of generic");
  check("toplevel.yaml", "- 1\n- 2\n", 1, "expected an object");
  check("typo.yaml", "dh:\n  - {a_m: 0, alpha_deg: 90, d_m: 0.1}\ntools: {}\n", 3,
        "tools: unknown key");
  check("dup.yaml", "name: a\nname: b\ndh: []\n", 2, "duplicate key");
  const std::string too_many = "dh:\n" + [] {
    std::string s;
    for (int i = 0; i < 13; ++i) s += "  - {a_m: 0, alpha_deg: 90, d_m: 0.1}\n";
    return s;
  }();
  check("many.yaml", too_many, 2, "expected a list of 1 to 12 rows");
  const std::string missing = dir.file("absent.yaml");
  EXPECT_TRUE(throws_file_error([&] { read_robot_file(missing); }, missing, 0, "cannot open"));
}

}  // namespace
}  // namespace vrreg::io
