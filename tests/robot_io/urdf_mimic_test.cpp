// SPDX-License-Identifier: Apache-2.0
// URDF mimic joints: a lifting column whose stages mimic a drive on a side branch, under a 6-axis
// arm (tests/data/urdf/lift_arm.urdf), against the same file with the mimic tags removed and the
// stages set by hand, and against FK composed on urdfdom's own tree with urdfdom's mimic values;
// then random trees with mimic joints on and off the chain (joints following chain joints before
// and after them, negative and fractional multipliers), the numeric IK, the joint-space model on
// a simulated cell, the tip and base links given by the caller, and the refusals.
#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <map>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>

#include "chain_test_support.hpp"
#include "coupled_cell.hpp"
#include "io_test_helpers.hpp"
#include "urdf_pose.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"
#include "vrreg/kinematics/numeric_ik.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/robot_io/robot_file.hpp"
#include "vrreg/robot_io/urdf_robot.hpp"
#include "vrreg_test.hpp"

namespace vrreg::io::mimic_test {
namespace {

using kinematics::JointVector;
using kinematics::SerialChain;
using vrreg::testing::read_text;
using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;

constexpr double kPi = std::numbers::pi;

std::string lift_arm_path() { return std::string(VRREG_TEST_DATA_DIR) + "/urdf/lift_arm.urdf"; }

std::string without_mimics(const std::string& xml) {
  return std::regex_replace(xml, std::regex("<mimic[^>]*/>"), "");
}

using vrreg::testing::to_eigen;

// FK on urdfdom's tree from `base` to `tip`: each joint's value is the variable of its name, or,
// for a mimic joint, urdfdom's multiplier times its source's variable plus the offset.
Eigen::Isometry3d tree_fk(const urdf::ModelInterface& model, const std::string& base,
                          const std::string& tip, const std::map<std::string, double>& value) {
  std::vector<urdf::JointConstSharedPtr> path;
  for (urdf::LinkConstSharedPtr l = model.getLink(tip); l && l->name != base; l = l->getParent()) {
    path.insert(path.begin(), l->parent_joint);
  }
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (const auto& j : path) {
    t = t * to_eigen(j->parent_to_joint_origin_transform);
    if (j->type == urdf::Joint::FIXED) continue;
    const double q = j->mimic
                         ? j->mimic->multiplier * value.at(j->mimic->joint_name) + j->mimic->offset
                         : value.at(j->name);
    const Eigen::Vector3d axis = Eigen::Vector3d(j->axis.x, j->axis.y, j->axis.z).normalized();
    Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
    if (j->type == urdf::Joint::PRISMATIC) {
      m.translation() = q * axis;
    } else {
      m.linear() = Eigen::AngleAxisd(q, axis).toRotationMatrix();
    }
    t = t * m;
  }
  return t;
}

std::map<std::string, double> by_name(const SerialChain& chain, const JointVector& q) {
  std::map<std::string, double> out;
  for (int i = 0; i < chain.n_joints(); ++i) {
    out[chain.couplings().variables[static_cast<std::size_t>(i)].name] = q(i);
  }
  return out;
}

using vrreg::testing::central_difference_jacobian;
using vrreg::testing::pose_gap;

JointVector random_joints(Random& rng, const SerialChain& chain) {
  return vrreg::testing::joints_within_limits(rng, chain);
}

TEST(UrdfMimic, TheLiftingColumnIsOneVariableDrivingTwoStages) {
  const SerialChain chain = read_urdf_robot(lift_arm_path(), {"", "tool0"});
  EXPECT_EQ(chain.n_rows(), 8);
  ASSERT_EQ(chain.n_joints(), 7);
  const kinematics::JointCouplings& c = chain.couplings();
  EXPECT_EQ(c.variables[0].name, "lift_drive");
  EXPECT_EQ(c.variables[0].type, kinematics::JointType::kPrismatic);
  EXPECT_EQ(c.variables[1].name, "shoulder_pan_joint");
  EXPECT_EQ(c.variables[6].name, "wrist_3_joint");
  EXPECT_EQ(c.rows[0], (kinematics::JointCoupling{0, 0.5, 0.0}));
  EXPECT_EQ(c.rows[1], (kinematics::JointCoupling{0, 0.5, 0.01}));
  EXPECT_EQ(c.rows[2], (kinematics::JointCoupling{1, 1.0, 0.0}));
  EXPECT_TRUE(chain.prismatic(0));
  EXPECT_FALSE(chain.wraps(0));
  EXPECT_TRUE(chain.wraps(6));
  // The drive's 0..0.8 m; the stages allow 0..0.8 and -0.02..0.82.
  EXPECT_DOUBLE_EQ(chain.limit(0).lower_rad, 0.0);
  EXPECT_DOUBLE_EQ(chain.limit(0).upper_rad, 0.8);
  EXPECT_EQ(chain.urdf_base_link(), "base_footprint");
  EXPECT_EQ(chain.urdf_tip_link(), "tool0");
}

TEST(UrdfMimic, ForwardKinematicsMatchesTheHandExpandedRobotAndUrdfdomsTree) {
  const std::string xml = read_text(lift_arm_path());
  const SerialChain chain = parse_urdf_robot(xml, "lift_arm.urdf", {"", "tool0"});
  const SerialChain expanded = parse_urdf_robot(without_mimics(xml), "expanded", {"", "tool0"});
  ASSERT_FALSE(expanded.coupled());
  ASSERT_EQ(expanded.n_joints(), 8);
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
  ASSERT_TRUE(model);
  Random rng(31);
  for (int trial = 0; trial < 200; ++trial) {
    const JointVector q = random_joints(rng, chain);
    JointVector by_hand(8);
    by_hand << 0.5 * q(0), 0.5 * q(0) + 0.01, q.tail<6>();
    const Eigen::Isometry3d t = kinematics::forward_kinematics(chain, q);
    EXPECT_LT(pose_gap(t, kinematics::forward_kinematics(expanded, by_hand)), 1e-12);
    EXPECT_LT(pose_gap(t, tree_fk(*model, "base_footprint", "tool0", by_name(chain, q))), 1e-12);
  }
}

TEST(UrdfMimic, JacobianMatchesCentralDifferences) {
  const SerialChain chain = read_urdf_robot(lift_arm_path(), {"", "camera_link"});
  Random rng(32);
  for (int trial = 0; trial < 20; ++trial) {
    const JointVector q = random_joints(rng, chain);
    const Eigen::MatrixXd j = kinematics::jacobian(chain, q);
    EXPECT_EIGEN_NEAR(j, central_difference_jacobian(chain, q, 1e-6), 1e-8);
  }
}

TEST(UrdfMimic, InverseKinematicsRoundTrips) {
  const SerialChain chain = read_urdf_robot(lift_arm_path(), {"", "tool0"});
  Random rng(33);
  for (int trial = 0; trial < 6; ++trial) {
    const JointVector q = random_joints(rng, chain);
    const Eigen::Isometry3d target = kinematics::forward_kinematics(chain, q);
    const kinematics::IkResult all = kinematics::inverse_kinematics(chain, target);
    ASSERT_TRUE(all.ok()) << all.message;
    for (const kinematics::IkSolution& s : all.solutions) {
      EXPECT_TRUE(chain.within_limits(s.q_rad));
      EXPECT_LT(pose_gap(kinematics::forward_kinematics(chain, s.q_rad), target), 1e-9);
    }
    // From joints near the true ones: a solution on the same branch (the lift makes the arm
    // redundant: a curve of joints reaches the pose, and the descent stops on it near the start).
    const kinematics::IkResult near =
        kinematics::inverse_kinematics_nearest(chain, target, q + JointVector::Constant(7, 0.02));
    ASSERT_TRUE(near.ok()) << near.message;
    const JointVector& found = near.solutions.front().q_rad;
    EXPECT_LT(pose_gap(kinematics::forward_kinematics(chain, found), target), 1e-9);
    EXPECT_LT((found - q).cwiseAbs().maxCoeff(), 0.05);
  }
}

// Random trees: a chain of moving joints with fixed joints between, side branches with drives,
// and mimic joints following a chain joint before or after them or a side drive; each against
// urdfdom's tree with urdfdom's mimic values, and the Jacobian against differences.
std::string random_mimic_urdf(Random& rng, int n, std::vector<std::string>& followers) {
  std::ostringstream x;
  x.precision(17);
  x << "<robot name=\"random\">\n<link name=\"l0\"/>\n";
  const auto origin = [&] {
    std::ostringstream o;
    o.precision(17);
    o << "<origin xyz=\"" << rng.uniform(-0.3, 0.3) << " " << rng.uniform(-0.3, 0.3) << " "
      << rng.uniform(-0.3, 0.3) << "\" rpy=\"" << rng.uniform(-kPi, kPi) << " "
      << rng.uniform(-1.5, 1.5) << " " << rng.uniform(-kPi, kPi) << "\"/>";
    return o.str();
  };
  const auto axis = [&] {
    std::ostringstream o;
    o.precision(17);
    o << "<axis xyz=\"" << rng.normal() << " " << rng.normal() << " " << rng.normal() << "\"/>";
    return o.str();
  };
  std::vector<std::string> names;
  std::vector<bool> slides;
  for (int i = 1; i <= n; ++i) {
    const bool slide = rng.uniform() < 0.3;
    names.push_back("j" + std::to_string(i));
    slides.push_back(slide);
  }
  // Side drives hang off l0: a revolute and a prismatic one.
  x << "<link name=\"side_r\"/><link name=\"side_p\"/>\n"
    << "<joint name=\"drive_r\" type=\"revolute\"><parent link=\"l0\"/><child link=\"side_r\"/>"
    << origin() << axis()
    << "<limit lower=\"-2\" upper=\"2\" effort=\"1\" velocity=\"1\"/></joint>\n"
    << "<joint name=\"drive_p\" type=\"prismatic\"><parent link=\"l0\"/><child link=\"side_p\"/>"
    << origin() << axis() << "<limit lower=\"-0.4\" upper=\"0.4\" effort=\"1\" velocity=\"1\"/>"
    << "</joint>\n";
  for (int i = 1; i <= n; ++i) {
    const std::string parent = "l" + std::to_string(i - 1);
    const std::string mid = "m" + std::to_string(i);
    const std::string child = "l" + std::to_string(i);
    x << "<link name=\"" << mid << "\"/><link name=\"" << child << "\"/>\n";
    x << "<joint name=\"f" << i << "\" type=\"fixed\"><parent link=\"" << parent
      << "\"/><child link=\"" << mid << "\"/>" << origin() << "</joint>\n";
    const bool slide = slides[static_cast<std::size_t>(i - 1)];
    x << "<joint name=\"" << names[static_cast<std::size_t>(i - 1)] << "\" type=\""
      << (slide ? "prismatic" : "revolute") << "\"><parent link=\"" << mid << "\"/><child link=\""
      << child << "\"/>" << origin() << axis() << "<limit lower=\"" << (slide ? -1.0 : -20.0)
      << "\" upper=\"" << (slide ? 1.0 : 20.0) << "\" effort=\"1\" velocity=\"1\"/>";
    // Every third joint follows: a side drive, or another chain joint that follows none.
    if (i % 3 == 2) {
      const double pick = rng.uniform();
      std::string source;
      if (pick < 0.3) {
        source = "drive_r";
      } else if (pick < 0.6) {
        source = "drive_p";
      } else {
        const int k = i == n ? 1 : (rng.uniform() < 0.5 ? 1 : std::min(n, i + 2));
        source = names[static_cast<std::size_t>(k - 1)];  // before or after it, never a follower
      }
      const double m = (rng.uniform() < 0.5 ? -1.0 : 1.0) * rng.uniform(0.2, 2.0);
      x << "<mimic joint=\"" << source << "\" multiplier=\"" << m << "\" offset=\""
        << rng.uniform(-0.05, 0.05) << "\"/>";
      followers.push_back(names[static_cast<std::size_t>(i - 1)]);
    }
    x << "</joint>\n";
  }
  x << "</robot>\n";
  return x.str();
}

TEST(UrdfMimic, RandomTreesMatchUrdfdomsTree) {
  Random rng(34);
  int coupled = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<std::string> followers;
    const int n = 3 + trial % 8;
    const std::string xml = random_mimic_urdf(rng, n, followers);
    const std::string tip = "l" + std::to_string(n);
    const SerialChain chain = parse_urdf_robot(xml, "random.urdf", {"", tip});
    const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
    ASSERT_TRUE(model);
    EXPECT_EQ(chain.n_rows(), n);
    EXPECT_EQ(chain.coupled(), !followers.empty());
    if (!chain.coupled()) continue;
    ++coupled;
    for (int k = 0; k < 10; ++k) {
      const JointVector q = random_joints(rng, chain);
      const Eigen::Isometry3d t = kinematics::forward_kinematics(chain, q);
      EXPECT_LT(pose_gap(t, tree_fk(*model, "l0", tip, by_name(chain, q))), 1e-12)
          << "trial " << trial << "\n"
          << xml;
      ASSERT_TRUE(chain.within_limits(q));
      // Every row stays within its own limits where the variables are within theirs.
      const JointVector rows = chain.row_values(q);
      for (int r = 0; r < chain.n_rows(); ++r) {
        EXPECT_GE(rows(r), chain.limits()[static_cast<std::size_t>(r)].lower_rad - 1e-12);
        EXPECT_LE(rows(r), chain.limits()[static_cast<std::size_t>(r)].upper_rad + 1e-12);
      }
      const Eigen::MatrixXd j = kinematics::jacobian(chain, q);
      EXPECT_EIGEN_NEAR(j, central_difference_jacobian(chain, q, 1e-6), 1e-7);
    }
  }
  EXPECT_GT(coupled, 30);
}

// The joint-space model on a simulated cell of the lifting column: as good on the mimic robot
// (7 commanded joints) as on the hand-expanded one (8, the stages set by hand), and far better
// than no correction.
TEST(UrdfMimic, JointModelOnASimulatedCellEqualsTheHandExpandedRobots) {
  if (vrreg::testing::sanitized()) GTEST_SKIP() << "fits two joint-space models";
  const std::string xml = read_text(lift_arm_path());
  const SerialChain chain = parse_urdf_robot(xml, "lift_arm.urdf", {"", "tool0"})
                                .with_tool(Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.05)));
  const SerialChain expanded = parse_urdf_robot(without_mimics(xml), "expanded", {"", "tool0"})
                                   .with_tool(chain.T_flange_tcp());
  Random rng(35);
  const vrreg::testing::CoupledCellRobot robot = vrreg::testing::as_built(chain, rng);
  JointVector home(7), half(7);
  home << 0.4, 0.3, -1.2, 1.5, -1.8, -1.57, 0.2;
  half << 0.35, 0.6, 0.4, 0.4, 0.6, 0.6, 0.8;
  const auto fiducials = vrreg::testing::coupled_cell(chain, robot, home, half, 160,
                                                      Eigen::Isometry3d::Identity(), 20e-6, rng);
  const auto targets = vrreg::testing::coupled_cell(chain, robot, home, half, 60,
                                                    Eigen::Isometry3d::Identity(), 20e-6, rng);
  std::vector<JointVector> q, q_rows;
  Points3 e(3, static_cast<Eigen::Index>(fiducials.size()));
  for (std::size_t j = 0; j < fiducials.size(); ++j) {
    q.push_back(fiducials[j].q);
    q_rows.push_back(chain.row_values(fiducials[j].q));
    e.col(static_cast<Eigen::Index>(j)) = fiducials[j].sensor_m - fiducials[j].nominal_m;
  }
  kinematics::JointErrorModelOptions options;
  options.max_joint_degree = 4;
  options.max_periodic_terms = 0;
  const auto model = kinematics::JointErrorModel::fit(chain, q, e, options);
  const auto hand = kinematics::JointErrorModel::fit(expanded, q_rows, e, options);
  double unc = 0, cor = 0, cor_hand = 0;
  for (const auto& t : targets) {
    const Eigen::Vector3d truth = t.actual_m - t.nominal_m;
    unc += truth.squaredNorm();
    cor += (truth - model.predict_m(t.q)).squaredNorm();
    cor_hand += (truth - hand.predict_m(chain.row_values(t.q))).squaredNorm();
  }
  const double n = static_cast<double>(targets.size());
  unc = std::sqrt(unc / n);
  cor = std::sqrt(cor / n);
  cor_hand = std::sqrt(cor_hand / n);
  RecordProperty("unc_rms_mm", std::to_string(1e3 * unc));
  RecordProperty("cor_rms_mm", std::to_string(1e3 * cor));
  EXPECT_GT(unc, 1e-3);
  EXPECT_LT(cor, 0.05 * unc);
  EXPECT_LE(cor, cor_hand + 1e-12);
}

TEST(UrdfMimic, TheTipMustBeNamedAndTheMessageSaysHow) {
  EXPECT_TRUE(throws_file_error([] { (void)read_urdf_robot(lift_arm_path()); }, lift_arm_path(), 0,
                                "several leaf links end 8 moving joints from the root "
                                "(camera_link, tool0): name the tip link (--tip-link NAME on the "
                                "command line, or tip_link in a robot YAML file"));
  EXPECT_EQ(read_urdf_robot(lift_arm_path(), {"", "camera_link"}).urdf_tip_link(), "camera_link");
}

TEST(UrdfMimic, LinksGivenByTheCallerAndByRobotFiles) {
  TempDir dir;
  const std::string yaml = dir.file("lift.yaml");
  std::ofstream(yaml) << "urdf: " << lift_arm_path() << "\ntip_link: tool0\n";
  EXPECT_EQ(load_robot(yaml).n_joints(), 7);
  EXPECT_EQ(load_robot(yaml, {"", "tool0"}).urdf_tip_link(), "tool0");
  EXPECT_TRUE(throws_file_error(
      [&] {
        (void)load_robot(yaml, {"", "camera_link"});
      },
      yaml, 2, "'tool0' here, 'camera_link' given besides: name one tip_link"));
  // Defaults (a model's remembered links) yield to the file's and to a robot that is no URDF.
  EXPECT_EQ(load_robot(yaml, {"", "camera_link", true}).urdf_tip_link(), "tool0");
  EXPECT_EQ(load_robot("ur5", {"", "tool0", true}).n_joints(), 6);
  const std::string bare = dir.file("bare.yaml");
  std::ofstream(bare) << "urdf: " << lift_arm_path() << "\n";
  EXPECT_EQ(load_robot(bare, {"", "camera_link"}).urdf_tip_link(), "camera_link");
  EXPECT_EQ(load_robot(lift_arm_path(), {"base_link", "tool0"}).urdf_base_link(), "base_link");
  try {
    (void)load_robot("ur5", {"", "tool0"});
    ADD_FAILURE() << "a tip link on a built-in robot was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "tip link 'tool0' given, but the robot is the built-in ur5: tip and base links "
                 "name links of a URDF (a .urdf file, or a robot file with \"urdf\")");
  }
  const std::string dh = dir.file("dh.yaml");
  std::ofstream(dh) << "dh:\n  - {a_m: 0, alpha_deg: 0, d_m: 0.1}\n";
  EXPECT_TRUE(throws_file_error(
      [&] {
        (void)load_robot(dh, {"", "tool0"});
      },
      dh, 1, "tip link 'tool0' given, but the robot is a DH table"));
}

// One refusal per broken mimic tag, each one line naming the file and the joint.
TEST(UrdfMimic, BrokenMimicTagsAreRefusedNamingTheJoint) {
  const std::string xml = read_text(lift_arm_path());
  const std::string lower = "<mimic joint=\"lift_drive\" multiplier=\"0.5\" offset=\"0\"/>";
  const std::string upper = "<mimic joint=\"lift_drive\" multiplier=\"0.5\" offset=\"0.01\"/>";
  ASSERT_NE(xml.find(lower), std::string::npos);
  ASSERT_NE(xml.find(upper), std::string::npos);
  const auto with = [&](const std::string& a, const std::string& b) {
    std::string out = xml;
    out.replace(out.find(lower), lower.size(), a);
    out.replace(out.find(upper), upper.size(), b);
    return out;
  };
  const auto refused = [&](const std::string& text, const std::string& fragment) {
    return throws_file_error(
        [&] {
          (void)parse_urdf_robot(text, "lift.urdf", {"", "tool0"});
        },
        "lift.urdf", 0, fragment);
  };
  EXPECT_TRUE(refused(with("<mimic joint=\"column_upper_joint\"/>", upper),
                      "joint 'column_lower_joint' mimics 'column_upper_joint', which mimics "
                      "'lift_drive': a mimic joint must follow a joint that is no mimic"));
  EXPECT_TRUE(refused(
      with("<mimic joint=\"column_upper_joint\"/>", "<mimic joint=\"column_lower_joint\"/>"),
      "joint 'column_lower_joint': its mimic tags form a cycle "
      "(column_lower_joint -> column_upper_joint -> column_lower_joint)"));
  EXPECT_TRUE(refused(with("<mimic joint=\"column_lower_joint\"/>", upper),
                      "joint 'column_lower_joint': its mimic tags form a cycle"));
  EXPECT_TRUE(
      refused(with("<mimic joint=\"spindle\"/>", upper),
              "joint 'column_lower_joint' mimics joint 'spindle', which is not in the URDF"));
  EXPECT_TRUE(refused(with("<mimic joint=\"lift_drive\" multiplier=\"0\"/>", upper),
                      "joint 'column_lower_joint' mimics 'lift_drive' with multiplier 0"));
  EXPECT_TRUE(refused(with("<mimic joint=\"arm_mount\"/>", upper),
                      "joint 'column_lower_joint' mimics 'arm_mount', which is not a revolute, "
                      "continuous or prismatic joint"));
  // Non-finite numbers: refused by urdfdom or here, as one line naming the file.
  for (const char* bad : {"nan", "inf", "1e999"}) {
    EXPECT_TRUE(refused(
        with(std::string("<mimic joint=\"lift_drive\" multiplier=\"") + bad + "\"/>", upper), ""))
        << bad;
  }
  // The stages' limits leave the drive no common range: refused naming the drive.
  std::string narrow = xml;
  const std::string limit = "<limit lower=\"0.0\" upper=\"0.4\"";
  narrow.replace(narrow.find(limit), limit.size(), "<limit lower=\"0.5\" upper=\"0.6\"");
  EXPECT_TRUE(refused(narrow,
                      "the limits of joint 'lift_drive' and of the joints that follow it "
                      "leave no common range"));
}

}  // namespace
}  // namespace vrreg::io::mimic_test
