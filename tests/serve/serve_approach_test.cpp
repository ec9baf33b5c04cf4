// SPDX-License-Identifier: Apache-2.0
// Approach directions on the service: `from` and `approach` on the line protocol, `from_rad` and
// `approach` on HTTP/JSON (single points and batches), their refusals, the audit log, and that a
// model without a lost-motion term answers exactly as without them.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "serve/http_api.hpp"
#include "serve/line_protocol.hpp"
#include "serve/service.hpp"
#include "serve/snippets.hpp"
#include "serve_test_support.hpp"
#include "urscript_text.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/measurement.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg_test.hpp"

// A namespace of its own: the unity build compiles this file with the other serve tests.
namespace vrreg::serve::testing::approach {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

PointRequest point_of(const std::string& line) {
  const LineRequest r = parse_line_request(line);
  EXPECT_TRUE(std::holds_alternative<PointRequest>(r)) << line;
  return std::holds_alternative<PointRequest>(r) ? std::get<PointRequest>(r) : PointRequest{};
}

std::string refusal_of(const std::string& line) {
  const LineRequest r = parse_line_request(line);
  EXPECT_TRUE(std::holds_alternative<BadRequest>(r)) << line;
  return std::holds_alternative<BadRequest>(r) ? std::get<BadRequest>(r).reason : std::string();
}

TEST(LineApproach, FromGivesTheSignOfEachJointsMove) {
  const PointRequest p =
      point_of("cell 1 2 3 joints 0.1 -0.2 0.3 0.5 from 0.0,-0.1 0.3 0.7 extrapolate");
  EXPECT_EQ(p.joints_rad, (std::vector<double>{0.1, -0.2, 0.3, 0.5}));
  EXPECT_EQ(p.from_rad, (std::vector<double>{0.0, -0.1, 0.3, 0.7}));
  EXPECT_EQ(p.approach_sign, (std::vector<double>{1, -1, 0, -1}));  // 0: the joint did not move
  EXPECT_TRUE(p.extrapolate);
  // `from` before `joints`, with an orientation after: the same signs.
  const PointRequest q = point_of("cell 1 2 3 FROM 0.2 0 joints 0.1 0 rotvec 0 0 0");
  EXPECT_EQ(q.approach_sign, (std::vector<double>{-1, 0}));
  EXPECT_EQ(q.orientation_form, OrientationForm::kRotationVector);
}

TEST(LineApproach, ApproachGivesTheSignsAsTheyAre) {
  const PointRequest p = point_of("cell 1 2 3 joints 0.1 0.2 0.3 approach -1 +1 -0 config 4");
  EXPECT_EQ(p.approach_sign, (std::vector<double>{-1, 1, 0}));
  EXPECT_FALSE(std::signbit(p.approach_sign[2]));
  EXPECT_TRUE(p.from_rad.empty());
  EXPECT_EQ(p.config, 4);
  // Signs alone, for a controller that keeps no joints: the model decides whether it needs them.
  EXPECT_EQ(point_of("cell 1 2 3 approach 1 -1").approach_sign, (std::vector<double>{1, -1}));
  // Without a direction: none, as before.
  EXPECT_TRUE(point_of("cell 1 2 3 joints 0.1 0.2").approach_sign.empty());
}

TEST(LineApproach, RefusesMalformedDirectionsWithTheReason) {
  EXPECT_THAT(refusal_of("cell 1 2 3 from 0.1 0.2"), HasSubstr("from without joints"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 0.2 from 0.1"),
              HasSubstr("from has 1 joints, joints 2"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 0.2 approach 1"),
              HasSubstr("approach has 1 signs"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 approach 2"), HasSubstr("not -1, 0 or 1"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 approach 0.5"), HasSubstr("not -1, 0 or 1"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 from x"), HasSubstr("from joint 'x'"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 from nan"), HasSubstr("not a finite angle"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 from"), HasSubstr("from without values"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 approach"), HasSubstr("approach without values"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 from 0 approach 1"),
              HasSubstr("unexpected 'approach'"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 from 0 from 0"), HasSubstr("unexpected 'from'"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 approach 1 approach 1"), HasSubstr("unexpected"));
  EXPECT_THAT(refusal_of("cell 1 2 3 joints 0.1 from 1e300"), HasSubstr("not a finite angle"));
  std::string seventeen = "cell 1 2 3 approach";
  for (int k = 0; k < 17; ++k) seventeen += " 1";
  EXPECT_THAT(refusal_of(seventeen), HasSubstr("more than 16"));
  // The reply keeps the request's orientation form when the direction is malformed.
  const LineRequest r = parse_line_request("cell 1 2 3 joints 0.1 from abc 0 0 0");
  ASSERT_TRUE(std::holds_alternative<BadRequest>(r));
  EXPECT_EQ(std::get<BadRequest>(r).form, OrientationForm::kKukaAbc);
}

TEST(HttpApproach, ReadsFromAndApproachForPointsAndBatches) {
  auto one = parse_http_correct(
      R"({"model":"c","sensor_mm":[1,2,3],"joints_rad":[0.5,0.1],"from_rad":[0.4,0.2]})", 10);
  ASSERT_TRUE(std::holds_alternative<HttpCorrectRequest>(one));
  const PointRequest& p = std::get<HttpCorrectRequest>(one).points.at(0);
  EXPECT_EQ(p.approach_sign, (std::vector<double>{1, -1}));
  EXPECT_EQ(p.from_rad, (std::vector<double>{0.4, 0.2}));
  auto batch = parse_http_correct(
      R"({"model":"c","points":[{"sensor_mm":[1,2,3],"joints_rad":[0.5],"approach":[-1]},)"
      R"({"sensor_mm":[4,5,6],"joints_rad":[0.5],"from_rad":[0.5]},{"sensor_mm":[4,5,6]}]})",
      10);
  ASSERT_TRUE(std::holds_alternative<HttpCorrectRequest>(batch));
  const auto& points = std::get<HttpCorrectRequest>(batch).points;
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0].approach_sign, (std::vector<double>{-1}));
  EXPECT_EQ(points[1].approach_sign, (std::vector<double>{0}));
  EXPECT_TRUE(points[2].approach_sign.empty());
  const std::vector<std::pair<std::string, std::string>> refused = {
      {R"({"model":"c","sensor_mm":[1,2,3],"from_rad":[0.4]})", "needs joints_rad"},
      {R"({"model":"c","sensor_mm":[1,2,3],"joints_rad":[1,2],"from_rad":[0.4]})",
       "1 angles, joints_rad 2"},
      {R"({"model":"c","sensor_mm":[1,2,3],"joints_rad":[1],"approach":[2]})", "-1, 0 or 1"},
      {R"({"model":"c","sensor_mm":[1,2,3],"joints_rad":[1],"approach":["+"]})",
       "expected a number"},
      {R"({"model":"c","sensor_mm":[1,2,3],"joints_rad":[1],"approach":[1,1]})",
       "2 signs, joints_rad 1"},
      {R"({"model":"c","sensor_mm":[1,2,3],"joints_rad":[1],"approach":[]})", "1 to 16 signs"},
      {R"({"model":"c","sensor_mm":[1,2,3],"joints_rad":[1],"from_rad":[0],"approach":[1]})",
       "not both"},
      {R"({"model":"c","points":[{"sensor_mm":[1,2,3],"joints_rad":[1],"from_rad":"x"}]})",
       "points[0].from_rad"},
  };
  for (const auto& [body, why] : refused) {
    const auto r = parse_http_correct(body, 10);
    ASSERT_TRUE(std::holds_alternative<PointAnswer>(r)) << body;
    EXPECT_EQ(std::get<PointAnswer>(r).code, ReplyCode::kMalformed) << body;
    EXPECT_THAT(std::get<PointAnswer>(r).reason, HasSubstr(why)) << body;
  }
}

// A model without a lost-motion term: a direction changes nothing in the answer (the same bytes),
// malformed directions are refused with code 1 and the connection goes on, and the audit log
// records what was asked.
TEST(ServeApproach, ADirectionOnAModelWithoutLostMotionAnswersAsWithout) {
  TempDir dir;
  const std::string path = dir.file("cell.json");
  write_model(path, InterpolationMethod::kKriging);
  ServeOptions o = local_options(path);
  o.audit.path = dir.file("audit.log");
  std::string with_from;
  {
    Service service(o, nullptr);
    service.start();
    ASSERT_FALSE(service.models().find("cell")->corrector().model().fiducials.empty());
    LineClient c(service.line_port());
    const MeasuredPoints cell = lattice_cell();
    const Eigen::Vector3d p = 500.0 * (cell.sensor_m.col(31) + cell.sensor_m.col(32));
    const std::string xyz = format_general(p.x(), 17) + " " + format_general(p.y(), 17) + " " +
                            format_general(p.z(), 17);
    const std::string plain = c.ask("cell " + xyz + "\n");
    ASSERT_THAT(plain, Not(StartsWith("(0,0,0,-")));
    with_from = c.ask("cell " + xyz + " joints 0.1 0.2 0.3 from 0.2 0.2 0.1\n");
    EXPECT_EQ(with_from, plain);
    EXPECT_EQ(c.ask("cell " + xyz + " joints 0.1 0.2 0.3 approach -1 0 1\n"), plain);
    EXPECT_EQ(c.ask("cell " + xyz + " from 0.2 0.2 0.1\n"), "(0,0,0,-1)\n");
    EXPECT_EQ(c.ask("cell " + xyz + " joints 0.1 approach 3\n"), "(0,0,0,-1)\n");
    EXPECT_EQ(c.ask("cell " + xyz + "\n"), plain);  // the connection goes on
    nlohmann::json batch = {{"model", "cell"}, {"points", nlohmann::json::array()}};
    batch["points"].push_back({{"sensor_mm", {p.x(), p.y(), p.z()}},
                               {"joints_rad", {0.1, 0.2}},
                               {"from_rad", {0.0, 0.3}}});
    batch["points"].push_back({{"sensor_mm", {p.x(), p.y(), p.z()}}});
    const std::string reply =
        http_request(service.http_port(), "POST", "/v1/correct", batch.dump());
    ASSERT_THAT(reply, StartsWith("200 "));
    const nlohmann::json results = nlohmann::json::parse(reply.substr(4))["results"];
    ASSERT_EQ(results.size(), 2u);
    EXPECT_EQ(results[0], results[1]);
    EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct",
                             R"({"model":"cell","sensor_mm":[1,2,3],"from_rad":[0.1]})"),
                StartsWith("400 "));
    service.stop();
  }
  const std::string log = read_text(dir.file("audit.log"));
  EXPECT_THAT(log, HasSubstr(R"("from_rad":[0.2,0.2,0.1],"approach":[-1,0,1])"));
  EXPECT_THAT(log, HasSubstr(R"("approach":[-1,0,1])"));
}

// The URScript has vrreg_correct_joints only when the model's answers need joints, and the line
// it sends (numbers as the controller's vrreg_text writes them) reads back as the joints and the
// approach signs the program meant.
TEST(SnippetApproach, UrscriptSendsJointsAndFromWhenTheModelNeedsThem) {
  SnippetOptions s;
  s.model = "cell";
  s.port = 30401;
  const std::string plain = urscript_client(s);
  EXPECT_THAT(plain, Not(HasSubstr("vrreg_correct_joints")));
  s.n_joints = 6;
  const std::string program = urscript_client(s);
  EXPECT_EQ(program.substr(0, plain.size()), plain);  // the functions before are unchanged
  EXPECT_THAT(program, HasSubstr("def vrreg_correct_joints(p_sensor_mm, q, q_from):\n"
                                 "  reply = vrreg_ask("));
  for (const char* part : {"\" joints\"", "\" from\"", "vrreg_text(q[5], 10000000)",
                           "vrreg_text(q_from[0], 10000000)", "vrreg_text(q_from[5], 10000000)"}) {
    EXPECT_THAT(program, HasSubstr(part)) << part;
  }
  EXPECT_THAT(program, Not(HasSubstr("q[6]")));
  const std::vector<float> q = {0.1f, -1.2f, 1.5f, -1.9f, -1.5708f, 0.25f};
  const std::vector<float> q_from = {0.2f, -1.3f, 1.5f, -1.8f, -1.5708f, 0.0f};
  std::vector<std::string> q_text, from_text;
  for (std::size_t j = 0; j < q.size(); ++j) {
    q_text.push_back(vrreg::testing::urscript_vrreg_text(q[j], 10000000));
    from_text.push_back(vrreg::testing::urscript_vrreg_text(q_from[j], 10000000));
  }
  const std::string line =
      urscript_joints_request_line(s, {"412.5000", "-90.0000", "310.0000"}, q_text, from_text);
  EXPECT_EQ(line.substr(0, 45), "cell 412.5000 -90.0000 310.0000 joints 0.1000");
  const PointRequest r = point_of(line.substr(0, line.size() - 1));
  ASSERT_EQ(r.joints_rad.size(), 6u);
  EXPECT_NEAR(r.joints_rad[1], -1.2, 1e-6);
  EXPECT_EQ(r.approach_sign, (std::vector<double>{-1, 1, 0, -1, 0, 1}));
  s.n_joints = 17;
  EXPECT_THROW((void)urscript_client(s), InputError);
}

// The KRL file's function is VRREG_CORRECT_JOINTS when the model's answers need joints: each
// E6AXIS joint (A1..A6, a seventh as E1) converted to rad and written after "joints" and "from",
// the line reading back as the joints and approach signs meant; the pose function refuses.
TEST(SnippetApproach, KrlSendsJointsAndFromWhenTheModelNeedsThem) {
  SnippetOptions s;
  s.model = "cell";
  s.port = 30401;
  EXPECT_THAT(krl_client(s), HasSubstr("DEFFCT BOOL VRREG_CORRECT(P_SENSOR_MM:IN,"));
  EXPECT_THAT(krl_client(s), Not(HasSubstr("Q_DEG")));
  s.n_joints = 6;
  const std::string program = krl_client(s);
  EXPECT_THAT(program, HasSubstr("DEFFCT BOOL VRREG_CORRECT_JOINTS(P_SENSOR_MM:IN, Q_DEG:IN, "
                                 "Q_FROM_DEG:IN, P_ROBOT_MM:OUT, SD_MM:OUT)\n"));
  for (const char* part :
       {"  DECL E6AXIS Q_DEG, Q_FROM_DEG\n", "  DECL REAL Q[6], F[6]\n",
        "  DEG_TO_RAD = 0.0174532925199433\n", "  Q[1] = Q_DEG.A1 * DEG_TO_RAD\n",
        "  F[6] = Q_FROM_DEG.A6 * DEG_TO_RAD\n",
        "  SWRITE(REQ[], STAT, OFS, \"cell %.6f %.6f %.6f joints\", P_SENSOR_MM.X, P_SENSOR_MM.Y, "
        "P_SENSOR_MM.Z)\n",
        "  SWRITE(REQ[], STAT, OFS, \" %.7f\", Q[6])\n", "  SWRITE(REQ[], STAT, OFS, \" from\")\n",
        "  SWRITE(REQ[], STAT, OFS, \" %.7f\", F[1])\n", "  SWRITE(REQ[], STAT, OFS, \"%c\", 10)\n",
        "  DECL CHAR REQ[512], REP[256]\n"}) {
    EXPECT_THAT(program, HasSubstr(part)) << part;
  }
  EXPECT_THAT(program, Not(HasSubstr("Q[7]")));
  // The SWRITEs' text, as krl_joints_request_line writes it, reads back as meant.
  const std::vector<double> q = {0.1, -1.2, 1.5, -1.9, -1.5708, 0.25};
  const std::vector<double> q_from = {0.2, -1.3, 1.5, -1.8, -1.5708, 0.0};
  const std::string line = krl_joints_request_line(s, {412.5, -90.0, 310.0}, q, q_from);
  EXPECT_EQ(line.substr(0, 57), "cell 412.500000 -90.000000 310.000000 joints 0.1000000 -1");
  const PointRequest r = point_of(line.substr(0, line.size() - 1));
  ASSERT_EQ(r.joints_rad.size(), 6u);
  EXPECT_NEAR(r.joints_rad[1], -1.2, 1e-12);
  EXPECT_EQ(r.approach_sign, (std::vector<double>{-1, 1, 0, -1, 0, 1}));
  // The LWR 4+: the seventh joint is E1.
  s.n_joints = 7;
  const std::string lwr = krl_client(s);
  EXPECT_THAT(lwr, HasSubstr("  Q[7] = Q_DEG.E1 * DEG_TO_RAD\n"));
  EXPECT_THAT(lwr, HasSubstr("  DECL REAL Q[7], F[7]\n"));
  EXPECT_THROW((void)krl_pose_client(s), InputError);
}

// A UR5 cell with lost motion, made here: a joint-space lattice visited in serpentine order (each
// location's approach directions from that order), the arm reaching FK(q - b / 2 * s), plus a
// smooth error and 0.01 mm noise; registered with kriging and the lost-motion term.
constexpr double kArcmin = M_PI / (180.0 * 60.0);

MeasuredPoints lost_motion_cell(const kinematics::SerialChain& arm, const Eigen::VectorXd& play) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -2, 1).normalized()).matrix();
  const Eigen::Vector3d t(0.5, -0.2, 1.8);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 1e-5);
  // Joint 1 on the inner loop, joint 2 on the middle one (both serpentine), joint 3 out and
  // back (0, 2, 4, 5, 3, 1): every moving joint arrives from both sides somewhere.
  std::vector<Eigen::VectorXd> path;
  int row = 0;
  for (const int a : {0, 2, 4, 5, 3, 1}) {
    for (int bi = 0; bi < 5; ++bi, ++row) {
      const int b = row / 5 % 2 == 0 ? bi : 4 - bi;
      for (int ci = 0; ci < 5; ++ci) {
        const int c = row % 2 == 0 ? ci : 4 - ci;
        Eigen::VectorXd q(6);
        q << -0.15 + 0.075 * c, -1.32 + 0.06 * b, 1.45 + 0.06 * a, -1.8 + 0.05 * ((a + b + c) % 3),
            -1.5708, 0.0;
        path.push_back(q);
      }
    }
  }
  MeasuredPoints cell;
  const auto n = static_cast<Eigen::Index>(path.size());
  cell.sensor_m.resize(3, n);
  cell.robot_m.resize(3, n);
  cell.joints_rad.resize(6, n);
  cell.approach_sign = Eigen::MatrixXd::Zero(6, n);
  Eigen::VectorXd sign = Eigen::VectorXd::Zero(6);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::VectorXd& q = path[static_cast<std::size_t>(i)];
    if (i > 0) update_approach_sign(path[static_cast<std::size_t>(i - 1)], q, sign);
    const Eigen::Vector3d nominal = kinematics::forward_kinematics(arm, q).translation();
    Eigen::Vector3d reached =
        kinematics::forward_kinematics(arm, q - 0.5 * play.cwiseProduct(sign)).translation();
    reached +=
        Eigen::Vector3d(1e-4 * std::sin(nominal.x() / 0.05), 8e-5 * std::cos(nominal.y() / 0.04),
                        6e-5 * std::sin(nominal.z() / 0.06));
    for (int k = 0; k < 3; ++k) reached(k) += noise(rng);
    cell.robot_m.col(i) = nominal;
    cell.sensor_m.col(i) = R.transpose() * (reached - t);
    cell.joints_rad.col(i) = q;
    cell.approach_sign.col(i) = sign;
  }
  return cell;
}

// The service with a lost-motion model: the same point asked from either side is answered
// apart by about the term, J_pos(q) b; asked without a direction, with the mean of the two and a
// wider sd; `approach` gives what `from` gives.
TEST(ServeApproach, AModelWithLostMotionAnswersEachDirectionAndWidensWithoutOne) {
  if (vrreg::testing::sanitized()) GTEST_SKIP();
  const kinematics::SerialChain arm = kinematics::ur5();
  Eigen::VectorXd play(6);
  play << 0.8 * kArcmin, 0.2 * kArcmin, 0.15 * kArcmin, 0.7 * kArcmin, 0.0, 0.0;
  RegisterOptions options;
  options.interpolation.method = InterpolationMethod::kKriging;
  options.robot = arm;
  options.lost_motion = LostMotionMode::kOn;
  const RegisterResult registered = register_fiducials(lost_motion_cell(arm, play), options);
  ASSERT_TRUE(registered.model.corrector.has_value());
  ASSERT_TRUE(registered.model.corrector->lost_motion().has_value());
  EXPECT_TRUE(registered.model.corrector->lost_motion()->applied);
  const Eigen::VectorXd fitted = registered.model.corrector->lost_motion()->play_rad / kArcmin;
  std::printf("fitted plays [arcmin]: %.3f %.3f %.3f %.3f %.3f %.3f\n", fitted(0), fitted(1),
              fitted(2), fitted(3), fitted(4), fitted(5));
  TempDir dir;
  const std::string path = dir.file("cell.json");
  io::write_model_json(path, registered.model);
  Service service(local_options(path), nullptr);
  service.start();
  LineClient c(service.line_port());
  // A point between the lattice's nodes, where the arm would really be from below.
  Eigen::VectorXd q(6);
  q << -0.02, -1.2, 1.6, -1.75, -1.5708, 0.0;
  const Eigen::Vector3d nominal = kinematics::forward_kinematics(arm, q).translation();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -2, 1).normalized()).matrix();
  const Eigen::Vector3d sensor_mm =
      1e3 * R.transpose() * (nominal - Eigen::Vector3d(0.5, -0.2, 1.8));
  std::string line = "cell";
  for (int k = 0; k < 3; ++k) line += " " + format_general(sensor_mm(k), 17);
  line += " joints";
  std::string below = " from", above = " from";
  for (int j = 0; j < 6; ++j) {
    line += " " + format_general(q(j), 17);
    below += " " + format_general(q(j) - 0.01, 17);
    above += " " + format_general(q(j) + 0.01, 17);
  }
  const auto numbers = [](const std::string& reply) {
    std::vector<double> v;
    std::stringstream in(reply.substr(1, reply.size() - 3));
    for (std::string x; std::getline(in, x, ',');) v.push_back(std::stod(x));
    return v;
  };
  const std::vector<double> up = numbers(c.ask(line + below + "\n"));
  const std::vector<double> down = numbers(c.ask(line + above + "\n"));
  const std::vector<double> none = numbers(c.ask(line + "\n"));
  ASSERT_EQ(up.size(), 4u);
  ASSERT_GT(up[3], 0.0);
  ASSERT_GT(none[3], 0.0);
  EXPECT_EQ(numbers(c.ask(line + " approach 1 1 1 1 1 1\n")), up);
  const Eigen::Vector3d apart_mm(up[0] - down[0], up[1] - down[1], up[2] - down[2]);
  const kinematics::Jacobian J = kinematics::jacobian(arm, q);
  const double term_mm = 1e3 * (J.topRows<3>() * play).norm();
  std::printf(
      "from either side: %.4f mm apart (the term |J b| %.4f mm); sd %.4f mm with a "
      "direction, %.4f mm without\n",
      apart_mm.norm(), term_mm, up[3], none[3]);
  EXPECT_NEAR(apart_mm.norm(), term_mm, 0.2 * term_mm);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(none[static_cast<std::size_t>(k)], 0.5 * (up[k] + down[k]), 1e-6);
  EXPECT_GT(none[3], up[3]);
}

}  // namespace
}  // namespace vrreg::serve::testing::approach
