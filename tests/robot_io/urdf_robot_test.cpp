// SPDX-License-Identifier: Apache-2.0
// Robots from URDF against two independent references: the FK composed on urdfdom's own tree
// (joint origins and motions, link by link) and Orocos KDL's chain built from the same tree; the
// URDF UR5 against the built-in ur5 (FK, IK, joint-space error model) to 1e-12.
#include "vrreg/robot_io/urdf_robot.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <filesystem>
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainjnttojacsolver.hpp>
#include <numbers>
#include <string>

#include "chain_test_support.hpp"
#include "io_test_helpers.hpp"
#include "urdf_pose.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/robot_io/robot_file.hpp"

namespace vrreg::io {
namespace {

using kinematics::JointVector;
using kinematics::SerialChain;
using vrreg::testing::read_text;
using vrreg::testing::TempDir;
using vrreg::testing::throws_file_error;

std::string urdf_path(const std::string& name) {
  return std::string(VRREG_TEST_DATA_DIR) + "/urdf/" + name;
}

using vrreg::testing::to_eigen;

Eigen::Isometry3d to_eigen(const KDL::Frame& f) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) t.linear()(r, c) = f.M(r, c);
    t.translation()(r) = f.p(r);
  }
  return t;
}

// The joints from `base` (an ancestor of `tip`) down to `tip` in urdfdom's tree, top first.
std::vector<urdf::JointConstSharedPtr> tree_path(const urdf::ModelInterface& model,
                                                 const std::string& base, const std::string& tip) {
  std::vector<urdf::JointConstSharedPtr> path;
  for (urdf::LinkConstSharedPtr l = model.getLink(tip); l && l->name != base; l = l->getParent()) {
    path.insert(path.begin(), l->parent_joint);
  }
  return path;
}

// Reference FK on urdfdom's tree: origin then motion, joint by joint.
Eigen::Isometry3d tree_fk(const std::vector<urdf::JointConstSharedPtr>& path,
                          const JointVector& q) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  int k = 0;
  for (const auto& j : path) {
    t = t * to_eigen(j->parent_to_joint_origin_transform);
    if (j->type == urdf::Joint::FIXED) continue;
    const Eigen::Vector3d axis(j->axis.x, j->axis.y, j->axis.z);
    Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
    if (j->type == urdf::Joint::PRISMATIC) {
      m.translation() = q(k) * axis;
    } else {
      m.linear() = Eigen::AngleAxisd(q(k), axis).toRotationMatrix();
    }
    t = t * m;
    ++k;
  }
  return t;
}

// KDL's chain of the same path: each segment's joint at its origin, its frame the origin.
KDL::Chain kdl_chain(const std::vector<urdf::JointConstSharedPtr>& path) {
  KDL::Chain chain;
  for (const auto& j : path) {
    const urdf::Pose& p = j->parent_to_joint_origin_transform;
    double x = 0, y = 0, z = 0, w = 1;
    p.rotation.getQuaternion(x, y, z, w);
    const KDL::Frame origin(KDL::Rotation::Quaternion(x, y, z, w),
                            KDL::Vector(p.position.x, p.position.y, p.position.z));
    const KDL::Vector axis(j->axis.x, j->axis.y, j->axis.z);
    KDL::Joint joint(j->name, KDL::Joint::None);
    if (j->type == urdf::Joint::PRISMATIC) {
      joint = KDL::Joint(j->name, origin.p, origin.M * axis, KDL::Joint::TransAxis);
    } else if (j->type != urdf::Joint::FIXED) {
      joint = KDL::Joint(j->name, origin.p, origin.M * axis, KDL::Joint::RotAxis);
    }
    chain.addSegment(KDL::Segment(j->name, joint, origin));
  }
  return chain;
}

JointVector random_joints(Random& rng, const SerialChain& chain) {
  return vrreg::testing::joints_within_limits(rng, chain);
}

using vrreg::testing::pose_gap;

struct UrdfCase {
  const char* file;
  const char* base;
  const char* tip;
  int n_joints;
};

class UrdfAgainstReferences : public ::testing::TestWithParam<UrdfCase> {};

TEST_P(UrdfAgainstReferences, ForwardKinematicsAndJacobianMatchUrdfdomAndKdl) {
  const UrdfCase c = GetParam();
  const std::string text = read_text(urdf_path(c.file));
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(text);
  ASSERT_TRUE(model);
  const SerialChain chain = read_urdf_robot(urdf_path(c.file), {"", ""});
  ASSERT_EQ(chain.n_joints(), c.n_joints);
  const auto path = tree_path(*model, c.base, c.tip);
  const KDL::Chain kdl = kdl_chain(path);
  ASSERT_EQ(static_cast<int>(kdl.getNrOfJoints()), c.n_joints);
  KDL::ChainFkSolverPos_recursive kdl_fk(kdl);
  KDL::ChainJntToJacSolver kdl_jac(kdl);
  Random rng(17);
  double worst_tree = 0.0, worst_kdl = 0.0, worst_jac = 0.0;
  for (int k = 0; k < 500; ++k) {
    const JointVector q = random_joints(rng, chain);
    const Eigen::Isometry3d t = kinematics::forward_kinematics(chain, q);
    worst_tree = std::max(worst_tree, pose_gap(t, tree_fk(path, q)));
    KDL::JntArray qk(static_cast<unsigned>(c.n_joints));
    for (int i = 0; i < c.n_joints; ++i) qk(static_cast<unsigned>(i)) = q(i);
    KDL::Frame f;
    ASSERT_GE(kdl_fk.JntToCart(qk, f), 0);
    worst_kdl = std::max(worst_kdl, pose_gap(t, to_eigen(f)));
    // KDL's Jacobian is of the tip point, in the base frame: vrreg's geometric Jacobian.
    KDL::Jacobian jk(static_cast<unsigned>(c.n_joints));
    ASSERT_GE(kdl_jac.JntToJac(qk, jk), 0);
    const kinematics::Jacobian j = kinematics::jacobian(chain, q);
    worst_jac = std::max(worst_jac, (j - jk.data).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(worst_tree, 1e-12) << c.file;
  EXPECT_LE(worst_kdl, 1e-12) << c.file;
  EXPECT_LE(worst_jac, 1e-12) << c.file;
}

INSTANTIATE_TEST_SUITE_P(TestRobots, UrdfAgainstReferences,
                         ::testing::Values(UrdfCase{"ur5.urdf", "base_link", "tool0", 6},
                                           UrdfCase{"arm7.urdf", "world", "flange", 7},
                                           UrdfCase{"ur5_on_rail.urdf", "world", "tool0", 7}),
                         [](const auto& param_info) {
                           std::string name = param_info.param.file;
                           return name.substr(0, name.find('.'));
                         });

TEST(UrdfRobot, PrismaticJointAndLimitsComeThrough) {
  const SerialChain chain = read_urdf_robot(urdf_path("ur5_on_rail.urdf"));
  EXPECT_EQ(chain.name(), "ur5_on_rail");
  EXPECT_TRUE(chain.row(0).prismatic());
  EXPECT_EQ(chain.limit(0).lower_rad, 0.0);
  EXPECT_EQ(chain.limit(0).upper_rad, 2.0);
  for (int i = 1; i < 7; ++i) EXPECT_FALSE(chain.row(i).prismatic());
  EXPECT_EQ(chain.family(), kinematics::ChainFamily::kGeneric);
  // The continuous wrist 3 gets +-360 deg.
  EXPECT_DOUBLE_EQ(chain.limit(6).upper_rad, 2.0 * std::numbers::pi);
  // Sliding the carriage by 0.5 m moves the tool by 0.5 m along the world x axis.
  JointVector q = JointVector::Zero(7);
  const Eigen::Vector3d p0 = kinematics::forward_kinematics(chain, q).translation();
  q(0) = 0.5;
  const Eigen::Vector3d p1 = kinematics::forward_kinematics(chain, q).translation();
  EXPECT_LE((p1 - p0 - Eigen::Vector3d(0.5, 0, 0)).norm(), 1e-15);
}

// "base" -> "tool0" of the ROS-Industrial style UR5 is the built-in ur5, DH table and all.
SerialChain urdf_ur5() { return read_urdf_robot(urdf_path("ur5.urdf"), {"base", "tool0"}); }

TEST(UrdfUr5, IsTheBuiltInUr5) {
  const SerialChain urdf = urdf_ur5();
  const SerialChain builtin = kinematics::ur5();
  ASSERT_EQ(urdf.family(), kinematics::ChainFamily::kUr);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(urdf.row(i).a_m, builtin.row(i).a_m, 1e-12) << i;
    EXPECT_NEAR(urdf.row(i).d_m, builtin.row(i).d_m, 1e-12) << i;
    EXPECT_NEAR(urdf.row(i).alpha_rad, builtin.row(i).alpha_rad, 1e-12) << i;
    EXPECT_NEAR(urdf.row(i).theta_offset_rad, builtin.row(i).theta_offset_rad, 1e-12) << i;
  }
  EXPECT_TRUE(urdf.tcp_is_flange_in_dh0());
  Random rng(5);
  for (int k = 0; k < 2000; ++k) {
    const JointVector q = random_joints(rng, builtin);
    const Eigen::Isometry3d t = kinematics::forward_kinematics(builtin, q);
    ASSERT_LE(pose_gap(kinematics::forward_kinematics(urdf, q), t), 1e-12);
    const kinematics::IkResult a = kinematics::inverse_kinematics(builtin, t);
    const kinematics::IkResult b = kinematics::inverse_kinematics(urdf, t);
    ASSERT_EQ(a.solutions.size(), b.solutions.size());
    for (std::size_t s = 0; s < a.solutions.size(); ++s) {
      EXPECT_EQ(a.solutions[s].config, b.solutions[s].config);
      EXPECT_LE((a.solutions[s].q_rad - b.solutions[s].q_rad).cwiseAbs().maxCoeff(), 1e-12);
    }
  }
}

TEST(UrdfUr5, JointErrorModelIsTheBuiltInUr5s) {
  const SerialChain urdf = urdf_ur5();
  const SerialChain builtin = kinematics::ur5();
  // A robot with joint offsets and a link-length error, seen at 60 random poses.
  Random rng(8);
  std::vector<JointVector> q;
  Points3 error(3, 60);
  for (int k = 0; k < 60; ++k) {
    q.push_back(random_joints(rng, builtin));
    JointVector qa = q.back();
    for (int i = 0; i < 6; ++i) qa(i) += 1e-3 * (i + 1) * std::sin(qa(i));
    std::vector<kinematics::DhRow> rows = builtin.rows();
    rows[1].a_m += 2e-4;
    const SerialChain actual("actual", rows, builtin.limits());
    error.col(k) = kinematics::forward_kinematics(actual, qa).translation() -
                   kinematics::forward_kinematics(builtin, q.back()).translation();
  }
  kinematics::JointErrorModelOptions options;
  options.joint_degrees = std::vector<int>(6, 1);
  const auto a = kinematics::JointErrorModel::fit(builtin, q, error, options);
  const auto b = kinematics::JointErrorModel::fit(urdf, q, error, options);
  EXPECT_EQ(a.rank(), b.rank());
  for (int k = 0; k < 20; ++k) {
    const JointVector qt = random_joints(rng, builtin);
    EXPECT_LE((a.predict_m(qt) - b.predict_m(qt)).norm(), 1e-12);
  }
}

// The joint-space error model on the arm on a linear axis: a rail with an offset and a scale
// error (a prismatic joint's error function is in metres), a skewed rail (its theta), a longer
// upper arm and joint offsets, seen at 150 poses, predicted at others.
TEST(UrdfRobot, JointErrorModelOnAPrismaticAxis) {
  const SerialChain nominal = read_urdf_robot(urdf_path("ur5_on_rail.urdf"));
  std::vector<kinematics::DhRow> rows = nominal.rows();
  rows[0].theta_offset_rad += 2e-4;
  rows[2].a_m += 1e-4;
  const SerialChain actual("actual", rows, nominal.limits(), nominal.T_base_dh0(),
                           nominal.T_flange_tcp());
  const auto error_at = [&](const JointVector& q) {
    JointVector qa = q;
    qa(0) += 3e-4 + 1e-3 * q(0);  // 0.3 mm offset, 1 mm per m
    for (int i = 1; i < 7; ++i) qa(i) += 2e-5 * i;
    return Eigen::Vector3d(kinematics::forward_kinematics(actual, qa).translation() -
                           kinematics::forward_kinematics(nominal, q).translation());
  };
  Random rng(21);
  std::vector<JointVector> q;
  Points3 error(3, 150);
  for (int k = 0; k < 150; ++k) {
    q.push_back(random_joints(rng, nominal));
    error.col(k) = error_at(q.back());
  }
  kinematics::JointErrorModelOptions options;
  options.joint_degrees = {1, 0, 0, 0, 0, 0, 0};
  options.gauss_newton_iterations = 5;
  const auto model = kinematics::JointErrorModel::fit(nominal, q, error, options);
  // Errors of ~1 mm are modelled to 1e-7 m: the first-order model plus Gauss-Newton stops at
  // ~1e-8 m on this chain (each error alone is fitted to 1e-16 m).
  EXPECT_GT(std::sqrt(error.colwise().squaredNorm().mean()), 1e-4);
  EXPECT_LE(model.residual_rms_m(), 1e-7);
  // Within the rail's fitted range: outside it the joint's error function stays at its end value.
  double lo = 2.0, hi = 0.0;
  for (const JointVector& qk : q) {
    lo = std::min(lo, qk(0));
    hi = std::max(hi, qk(0));
  }
  double worst = 0.0;
  for (int k = 0; k < 50; ++k) {
    JointVector qt = random_joints(rng, nominal);
    qt(0) = rng.uniform(lo, hi);
    worst = std::max(worst, (model.predict_m(qt) - error_at(qt)).norm());
  }
  EXPECT_LE(worst, 1e-7);
}

TEST(UrdfRobot, RobotFileNamesAUrdfChain) {
  TempDir dir;
  std::filesystem::copy_file(urdf_path("ur5.urdf"), dir.file("ur5.urdf"));
  const std::string file =
      dir.write("cell.yaml",
                "name: cell-ur5\nurdf: ur5.urdf\nbase_link: base\ntip_link: tool0\n"
                "family: ur\ntool: {xyz_mm: [0, 0, 45.5]}\n");
  const SerialChain chain = load_robot(file);
  EXPECT_EQ(chain.name(), "cell-ur5");
  EXPECT_EQ(chain.family(), kinematics::ChainFamily::kUr);
  EXPECT_NEAR(chain.T_flange_tcp().translation().z(), 0.0455, 1e-15);
  // A URDF path given directly: root to the deepest leaf (base_link -> tool0).
  const SerialChain direct = load_robot(urdf_path("ur5.urdf"));
  const JointVector q = JointVector::Constant(6, 0.3);
  const Eigen::Isometry3d rotated =
      Eigen::Isometry3d(Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitZ())) *
      kinematics::forward_kinematics(kinematics::ur5(), q);
  EXPECT_LE(pose_gap(kinematics::forward_kinematics(direct, q), rotated), 1e-12);
  // base_link is "base" turned half a turn about joint 1: still the UR structure (the DH table
  // of the built-in ur5, the half turn in the base transform), so the closed-form IK and
  // everything that needs it (`vrreg plan`) take the file as given.
  ASSERT_EQ(direct.family(), kinematics::ChainFamily::kUr);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(direct.row(i).a_m, kinematics::ur5().row(i).a_m) << i;
    EXPECT_EQ(direct.row(i).alpha_rad, kinematics::ur5().row(i).alpha_rad) << i;
    EXPECT_EQ(direct.row(i).d_m, kinematics::ur5().row(i).d_m) << i;
  }
  const kinematics::IkResult ik =
      kinematics::inverse_kinematics(direct, kinematics::forward_kinematics(direct, q));
  ASSERT_TRUE(ik.ok()) << ik.message;
  double nearest = 1.0;
  for (const kinematics::IkSolution& s : ik.solutions) {
    nearest = std::min(nearest, (s.q_rad - q).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(nearest, 1e-9);
}

TEST(UrdfRobot, BadFilesAreOneLineErrorsNamingTheFile) {
  TempDir dir;
  const std::string head = "<robot name='r'><link name='a'/><link name='b'/>";
  const auto joint = [](const std::string& type, const std::string& extra = "") {
    return "<joint name='j' type='" + type + "'><parent link='a'/><child link='b'/>" +
           "<axis xyz='0 0 1'/>" + extra + "</joint>";
  };
  const std::string limit = "<limit lower='-1' upper='1' effort='1' velocity='1'/>";
  const struct {
    const char* name;
    std::string text;
    const char* fragment;
  } cases[] = {
      {"malformed.urdf", "<robot name='r'><link name='a'>", "not a valid URDF"},
      {"missing.urdf", "<robot name='r'><link name='a'/>" + joint("revolute", limit) + "</robot>",
       "not a valid URDF"},
      {"loop.urdf",
       head + joint("revolute", limit) +
           "<joint name='k' type='fixed'><parent link='b'/><child link='a'/></joint></robot>",
       "not a valid URDF"},
      {"floating.urdf", head + joint("floating") + "</robot>", "floating or planar"},
      {"nolimit.urdf", head + joint("revolute") + "</robot>", "not a valid URDF"},
      {"fixed.urdf", head + joint("fixed") + "</robot>", "no moving joint"},
      {"flat.urdf",
       head + joint("revolute", "<limit lower='1' upper='1' effort='1' velocity='1'/>") +
           "</robot>",
       "not below upper limit"},
      {"empty.urdf", "", "not a valid URDF"},
  };
  for (const auto& c : cases) {
    const std::string path = dir.write(c.name, c.text);
    EXPECT_TRUE(throws_file_error([&] { (void)read_urdf_robot(path); }, path, 0, c.fragment))
        << c.name;
  }
  const std::string good = urdf_path("ur5.urdf");
  EXPECT_TRUE(throws_file_error(
      [&] {
        (void)read_urdf_robot(good, {"", "hand"});
      },
      good, 0, "tip link 'hand' is not in the URDF"));
  EXPECT_TRUE(throws_file_error(
      [&] {
        (void)read_urdf_robot(good, {"tool0", "base"});
      },
      good, 0, "passes moving joint"));
}

TEST(UrdfRobot, ALinkWithTwoParentsIsRefused) {
  TempDir dir;
  const std::string limit = "<limit lower='-1' upper='1' effort='1' velocity='1'/>";
  const auto joint = [&](const std::string& name, const std::string& parent,
                         const std::string& child) {
    return "<joint name='" + name + "' type='revolute'><parent link='" + parent +
           "'/><child link='" + child + "'/><axis xyz='0 0 1'/>" + limit + "</joint>";
  };
  // a -> b -> c and a -> c, in either name order (urdfdom kept whichever joint sorts last).
  for (const auto& [first, second] : {std::pair{"j1", "j2"}, std::pair{"j2", "j1"}}) {
    const std::string path = dir.write("two_parents.urdf",
                                       "<robot name='r'><link name='a'/><link name='b'/>"
                                       "<link name='c'/>" +
                                           joint("j0", "a", "b") + joint(first, "a", "c") +
                                           joint(second, "b", "c") + "</robot>");
    EXPECT_TRUE(throws_file_error([&] { (void)read_urdf_robot(path); }, path, 0,
                                  "link 'c' is the child of two joints"));
  }
}

TEST(UrdfRobot, DeepNestingIsRefusedWithTheLimit) {
  TempDir dir;
  const std::string ur5 = read_text(urdf_path("ur5.urdf"));
  const std::size_t end = ur5.rfind("</robot>");
  ASSERT_NE(end, std::string::npos);
  // The UR5 with an extension element nested `levels` deep, as in `fragment`.
  const auto nested = [&](int levels, const std::string& open, const std::string& close) {
    std::string text = ur5.substr(0, end);
    for (int i = 0; i < levels; ++i) text += open;
    for (int i = 0; i < levels; ++i) text += close;
    return text + "</robot>";
  };
  // 60 000 levels overflowed TinyXML's recursion (a crash); the limit is refused by name.
  const struct {
    const char* name;
    std::string text;
  } deep[] = {
      {"deep.urdf", nested(60000, "<a>", "</a>")},
      {"at_limit.urdf", nested(256, "<gazebo>", "</gazebo>")},
      // Markup TinyXML reads as a start tag, whatever the quotes or comments around it hold.
      {"quoted.urdf", nested(60000, "<a x='/>' y = \"</a>\">", "</a>")},
      {"commented.urdf", nested(300, "<!-- </a> --><a><![CDATA[</a>]]>", "</a>")},
  };
  for (const auto& c : deep) {
    const std::string path = dir.write(c.name, c.text);
    EXPECT_TRUE(throws_file_error([&] { (void)read_urdf_robot(path); }, path, 0,
                                  "XML elements nest deeper than 256 levels"))
        << c.name;
  }
  // Up to the limit (the robot element is one level) the file is read as before.
  const std::string ok = dir.write("ok.urdf", nested(255, "<gazebo>", "</gazebo>"));
  EXPECT_EQ(read_urdf_robot(ok).n_joints(), 6);
  const std::string flat = dir.write("flat.urdf", nested(60000, "<a/>", ""));
  EXPECT_EQ(read_urdf_robot(flat).n_joints(), 6);
}

TEST(UrdfRobot, ADirectoryOrAFifoIsNamedForWhatItIs) {
  TempDir dir;
  const std::string folder = dir.file("robot.urdf");
  std::filesystem::create_directory(folder);
  EXPECT_TRUE(throws_file_error([&] { (void)load_robot(folder); }, folder, 0, "is a directory"));
  const std::string fifo = dir.file("robot.yaml");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_TRUE(throws_file_error([&] { (void)load_robot(fifo); }, fifo, 0, "is a FIFO"));
  try {
    (void)load_robot(dir.file("absent.urdf"));
    ADD_FAILURE() << "an absent robot file was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no robot file by that name"), std::string::npos);
  }
}

}  // namespace
}  // namespace vrreg::io
