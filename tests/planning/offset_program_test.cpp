// SPDX-License-Identifier: Apache-2.0
// Hand-eye planning: the tilted poses keep every location's TCP position and arm
// configuration and make the marker offset observable; the robot programs written from the plan
// parse (a small URScript and KRL reader) and their joints reproduce the plan's poses by FK.
#include <cctype>
#include <optional>
#include <sstream>

#include "planning_fixtures.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/planning/offset_poses.hpp"
#include "vrreg/planning/plan.hpp"
#include "vrreg/planning/robot_program.hpp"
#include "vrreg/registration/marker_offset.hpp"
#include "vrreg_test.hpp"

namespace vrreg::planning {
namespace {

using kinematics::SerialChain;

using testing::ur5_with_sphere;

PlanResult small_plan(const SerialChain& chain, double tilt_deg, OffsetPoseSummary* summary) {
  PlanOptions o;
  o.halfwidth_m = 0.02;
  o.spacing_m = 0.02;
  PlanResult plan = make_plan(chain, {{"A", {0.42, -0.12, 0.25}}, {"B", {0.48, 0.05, 0.28}}}, o);
  EXPECT_TRUE(plan.ok()) << plan.message;
  if (tilt_deg > 0.0) *summary = add_offset_poses(chain, plan, o.arm, tilt_deg * M_PI / 180.0);
  return plan;
}

std::vector<Eigen::Isometry3d> flange_poses(const SerialChain& chain, const PlanResult& plan) {
  const SerialChain flange = chain.with_tool(Eigen::Isometry3d::Identity());
  std::vector<Eigen::Isometry3d> out;
  for (const PlannedLocation& l : plan.locations)
    out.push_back(kinematics::forward_kinematics(flange, l.q_rad));
  return out;
}

TEST(OffsetPoses, TiltedAtTheVolumeCornersKeepingConfigurationAndObservable) {
  const SerialChain chain = ur5_with_sphere();
  OffsetPoseSummary unused;
  const PlanResult flat = small_plan(chain, 0.0, &unused);
  OffsetPoseSummary summary;
  const PlanResult tilted = small_plan(chain, 20.0, &summary);
  EXPECT_EQ(summary.n_unreachable, 0);
  ASSERT_EQ(summary.n_added, 36);
  ASSERT_EQ(tilted.locations.size(), flat.locations.size() + 36);
  const std::vector<Eigen::Matrix3d> tilts = offset_tilts(20.0 * M_PI / 180.0);
  for (std::size_t k = 0; k < tilted.locations.size(); ++k) {
    const PlannedLocation& l = tilted.locations[k];
    const Eigen::Isometry3d tcp = kinematics::forward_kinematics(chain, l.q_rad);
    EXPECT_EIGEN_NEAR(tcp.translation(), l.robot_m, 1e-12);
    if (k >= 36) {  // the plan's own locations, unchanged after the offset block
      EXPECT_EQ(l.point, flat.locations[k - 36].point);
      EXPECT_EIGEN_NEAR(l.q_rad, flat.locations[k - 36].q_rad, 0.0);
      continue;
    }
    EXPECT_EQ(l.point.rfind(kOffsetPosePrefix, 0), 0u) << l.point;
    EXPECT_EQ(l.role, Role::kFiducial);
    EXPECT_EIGEN_NEAR(tcp.linear(), tool_pointing_down() * tilts[k % 4], 1e-12);
    EXPECT_EQ(l.config, flat.locations.front().config) << l.point;
  }
  EXPECT_LT(orientation_spread(flange_poses(chain, flat)), 1e-8);
  EXPECT_GT(orientation_spread(flange_poses(chain, tilted)), 0.05);
  PlanResult empty;
  EXPECT_THROW(add_offset_poses(chain, empty, ArmConfigurationOptions{}, 0.1), InputError);
  PlanResult copy = flat;
  EXPECT_THROW(add_offset_poses(chain, copy, ArmConfigurationOptions{}, 1.2), InputError);
}

std::vector<ProgramLocation> program_locations(const PlanResult& plan) {
  std::vector<ProgramLocation> out;
  for (const PlannedLocation& l : plan.locations)
    out.push_back({l.point, l.role, l.config.to_string(), l.q_rad});
  return out;
}

// A whole string as one number (std::regex is avoided: GCC 12 warns inside it under sanitizers).
bool number(const std::string& text, double& value) {
  if (text.empty() || text.find_first_of(" ,") != std::string::npos) return false;
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size();
}

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// "PREFIX<number>SUFFIX" with nothing else.
bool call_of_number(const std::string& line, const std::string& prefix, const std::string& suffix) {
  double v = 0.0;
  return starts_with(line, prefix) && ends_with(line, suffix) &&
         number(line.substr(prefix.size(), line.size() - prefix.size() - suffix.size()), v);
}

// `PREFIX"TEXT"SUFFIX` with no quote or backslash in TEXT.
bool call_of_string(const std::string& line, const std::string& prefix, const std::string& suffix) {
  if (!starts_with(line, prefix + "\"") || !ends_with(line, "\"" + suffix)) return false;
  const std::string inner =
      line.substr(prefix.size() + 1, line.size() - prefix.size() - suffix.size() - 2);
  return inner.find_first_of("\"\\") == std::string::npos;
}

// "  movej([q1, ..., q6], a=A, v=V)": the joints, or none when the line is not such a call.
std::optional<Eigen::VectorXd> movej_joints(const std::string& line) {
  const std::string prefix = "  movej([";
  const std::size_t close = line.find(']');
  if (!starts_with(line, prefix) || close == std::string::npos) return std::nullopt;
  std::vector<double> q;
  std::stringstream list(line.substr(prefix.size(), close - prefix.size()));
  std::string item;
  while (std::getline(list, item, ',')) {
    if (!item.empty() && item.front() == ' ') item.erase(0, 1);
    double v = 0.0;
    if (!number(item, v)) return std::nullopt;
    q.push_back(v);
  }
  const std::string rest = line.substr(close + 1);  // ", a=A, v=V)"
  const std::size_t v_at = rest.find(", v=");
  double a = 0.0, v = 0.0;
  if (!starts_with(rest, ", a=") || v_at == std::string::npos || !ends_with(rest, ")") ||
      !number(rest.substr(4, v_at - 4), a) ||
      !number(rest.substr(v_at + 4, rest.size() - v_at - 5), v)) {
    return std::nullopt;
  }
  return Eigen::Map<const Eigen::VectorXd>(q.data(), static_cast<Eigen::Index>(q.size()));
}

// A small URScript reader: one program `def NAME():` ... `end`, then `NAME()`; inside, only
// comments, textmsg, movej with 6 joints and a, v, sleep and blocking popups, with balanced
// quotes. Returns the movej joints in order.
std::vector<Eigen::VectorXd> parse_urscript(const std::string& text, int& popups) {
  std::istringstream in(text);
  std::string line, name;
  std::vector<Eigen::VectorXd> joints;
  enum { kBefore, kInside, kAfter, kCalled } state = kBefore;
  popups = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line.find_first_not_of(' ') == std::string::npos) continue;
    if (line[line.find_first_not_of(' ')] == '#') continue;
    if (state == kBefore) {
      EXPECT_TRUE(starts_with(line, "def ") && ends_with(line, "():")) << line;
      name = line.substr(4, line.size() - 7);
      EXPECT_FALSE(name.empty());
      for (const char c : name)
        EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '_');
      state = kInside;
    } else if (state == kInside) {
      if (line == "end") {
        state = kAfter;
      } else if (const std::optional<Eigen::VectorXd> q = movej_joints(line)) {
        EXPECT_EQ(q->size(), 6) << line;
        joints.push_back(*q);
      } else if (call_of_string(line, "  popup(", ", \"vrreg\", False, False, blocking=True)")) {
        ++popups;
      } else {
        EXPECT_TRUE(call_of_number(line, "  sleep(", ")") ||
                    call_of_string(line, "  textmsg(", ")"))
            << line;
      }
    } else if (state == kAfter) {
      EXPECT_EQ(line, name + "()");
      state = kCalled;
    } else {
      ADD_FAILURE() << "text after the program call: " << line;
    }
  }
  EXPECT_EQ(state, kCalled);
  return joints;
}

// "  PTP {A1 x, A2 y, ...}" with the axes `axes` in order: the joints [rad], or none.
std::optional<Eigen::VectorXd> ptp_joints(const std::string& line,
                                          const std::vector<std::string>& axes) {
  if (!starts_with(line, "  PTP {") || !ends_with(line, "}")) return std::nullopt;
  std::stringstream list(line.substr(7, line.size() - 8));
  std::string item;
  Eigen::VectorXd q(static_cast<Eigen::Index>(axes.size()));
  std::size_t k = 0;
  while (std::getline(list, item, ',')) {
    if (!item.empty() && item.front() == ' ') item.erase(0, 1);
    double v = 0.0;
    if (k >= axes.size() || !starts_with(item, axes[k] + " ") ||
        !number(item.substr(axes[k].size() + 1), v)) {
      return std::nullopt;
    }
    q(static_cast<Eigen::Index>(k++)) = v * M_PI / 180.0;
  }
  if (k != axes.size()) return std::nullopt;
  return q;
}

TEST(RobotProgram, UrScriptParsesAndReproducesThePlanByFk) {
  const SerialChain chain = ur5_with_sphere();
  OffsetPoseSummary summary;
  const PlanResult plan = small_plan(chain, 20.0, &summary);
  ProgramOptions options;
  options.repeats = 7;
  const std::string text =
      robot_program(program_locations(plan), ProgramFormat::kUrScript, options);
  int popups = 0;
  const std::vector<Eigen::VectorXd> joints = parse_urscript(text, popups);
  ASSERT_EQ(joints.size(), plan.locations.size());
  EXPECT_EQ(popups, static_cast<int>(plan.locations.size()));
  EXPECT_NE(text.find("take 7 tracker readings"), std::string::npos);
  for (std::size_t k = 0; k < joints.size(); ++k) {
    const Eigen::Isometry3d planned =
        kinematics::forward_kinematics(chain, plan.locations[k].q_rad);
    const Eigen::Isometry3d programmed = kinematics::forward_kinematics(chain, joints[k]);
    EXPECT_EIGEN_NEAR(programmed.translation(), plan.locations[k].robot_m, 1e-9);
    EXPECT_EIGEN_NEAR(programmed.linear(), planned.linear(), 1e-9);
  }
}

TEST(RobotProgram, KrlParsesAndReproducesThePlanByFk) {
  const SerialChain chain = ur5_with_sphere();
  OffsetPoseSummary summary;
  const PlanResult plan = small_plan(chain, 20.0, &summary);
  const std::string text = robot_program(program_locations(plan), ProgramFormat::kKrl);
  std::istringstream in(text);
  std::string line;
  std::size_t k = 0, halts = 0;
  bool def = false, end = false;
  while (std::getline(in, line)) {
    def = def || line == "DEF vrreg_plan( )";
    end = end || line == "END";
    halts += line == "  HALT" ? 1 : 0;
    if (!starts_with(line, "  PTP")) continue;
    const std::optional<Eigen::VectorXd> q = ptp_joints(line, {"A1", "A2", "A3", "A4", "A5", "A6"});
    ASSERT_TRUE(q.has_value()) << line;
    ASSERT_LT(k, plan.locations.size());
    EXPECT_EIGEN_NEAR(kinematics::forward_kinematics(chain, *q).translation(),
                      plan.locations[k].robot_m, 1e-9);
    ++k;
  }
  EXPECT_TRUE(def && end);
  EXPECT_EQ(k, plan.locations.size());
  EXPECT_EQ(halts, plan.locations.size());
}

TEST(RobotProgram, LwrKrlUsesE1ForTheThirdJointAndCsvHasEveryRow) {
  std::vector<ProgramLocation> l{
      {"F0", Role::kFiducial, "", Eigen::VectorXd::LinSpaced(7, 0.1, 0.7)}};
  const std::string krl = robot_program(l, ProgramFormat::kKrl);
  EXPECT_NE(krl.find("PTP {A1 5.729577951, A2 11.459155903, E1 17.188733854, A3 22.918311805"),
            std::string::npos)
      << krl;
  const std::string csv = robot_program(l, ProgramFormat::kJointCsv);
  EXPECT_NE(csv.find("order,point,role,config,q1_rad"), std::string::npos);
  EXPECT_NE(csv.find("1,F0,fiducial,,0.10000000000000001"), std::string::npos) << csv;
  EXPECT_THROW(robot_program(l, ProgramFormat::kUrScript), InputError);  // 7 joints
  EXPECT_THROW(robot_program({}, ProgramFormat::kJointCsv), InputError);
  EXPECT_THROW(parse_program_format("rapid"), InputError);
}

}  // namespace
}  // namespace vrreg::planning
