// SPDX-License-Identifier: Apache-2.0
// Orientations through the service: a request with the marker's measured orientation (rotation
// vector, quaternion or KUKA A, B, C) is answered with the pose to command in the same form, the
// numbers `vrreg::correct` gives for that orientation; the robot-side snippets' pose requests are
// answered; a model without an orientation field refuses, in the form the client reads.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "orientation_cell.hpp"
#include "serve/line_protocol.hpp"
#include "serve/service.hpp"
#include "serve/snippets.hpp"
#include "serve_test_support.hpp"
#include "urscript_text.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/rotation.hpp"

namespace vrreg::serve::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

std::string number(double v) { return format_general(v, 17); }

// The pose request for a target, the orientation in `form`.
std::string pose_line(const Location& target, OrientationForm form) {
  std::string line = "cell";
  for (int a = 0; a < 3; ++a) line += " " + number(units::m_to_mm(target.sensor_m(a)));
  const Eigen::Matrix3d R = target.q_sensor_marker->toRotationMatrix();
  switch (form) {
    case OrientationForm::kRotationVector: {
      const Eigen::Vector3d w = rotation_log(R);
      line += " rotvec " + number(w.x()) + " " + number(w.y()) + " " + number(w.z());
      break;
    }
    case OrientationForm::kKukaAbc: {
      const Eigen::Vector3d abc = kuka_abc_deg(R);
      line += " abc " + number(abc(0)) + " " + number(abc(1)) + " " + number(abc(2));
      break;
    }
    default: {
      const Eigen::Quaterniond& q = *target.q_sensor_marker;
      line += " quat " + number(q.x()) + " " + number(q.y()) + " " + number(q.z()) + " " +
              number(q.w());
    }
  }
  return line + "\n";
}

// The reply `vrreg::correct` gives for the request as the service reads it.
std::string expected_pose_reply(const RegistrationModel& model, const std::string& line) {
  const auto request = std::get<PointRequest>(parse_line_request(line.substr(0, line.size() - 1)));
  MeasuredPoints p;
  p.sensor_m = request.sensor_mm / units::kMillimetresPerMetre;
  p.q_sensor_marker = {*request.q_sensor_marker};
  const CorrectResult r = correct(model, p);
  if (r.correction.stencils[0].status != StencilStatus::kOk ||
      r.orientation->status[0] != StencilStatus::kOk) {
    return format_line_reply(PointAnswer::refusal(ReplyCode::kNotCorrectable, ""),
                             request.orientation_form);
  }
  PointAnswer a;
  a.robot_mm = units::m_to_mm(1.0) * r.correction.corrected_robot_m.col(0);
  a.sd_mm = units::m_to_mm(r.correction.predicted_sd_m(0));
  a.q_robot_marker = Eigen::Quaterniond(r.orientation->corrected_R_robot_marker[0]);
  a.angle_sd_rad = r.orientation->predicted_sd_rad(0);
  return format_line_reply(a, request.orientation_form);
}

std::vector<double> numbers_of(const std::string& reply) {
  std::vector<double> out;
  std::string body = reply.substr(1, reply.find(')') - 1);
  std::size_t start = 0;
  while (start <= body.size()) {
    const std::size_t comma = std::min(body.find(',', start), body.size());
    out.push_back(std::stod(body.substr(start, comma - start)));
    start = comma + 1;
  }
  return out;
}

// The orientation a reply carries, in `form`, as a rotation.
Eigen::Matrix3d orientation_of(const std::vector<double>& v, OrientationForm form) {
  switch (form) {
    case OrientationForm::kRotationVector:
      return rotation_exp({v[3], v[4], v[5]});
    case OrientationForm::kKukaAbc:
      return rotation_from_kuka_abc_deg({v[3], v[4], v[5]});
    default:
      return Eigen::Quaterniond(v[6], v[3], v[4], v[5]).normalized().toRotationMatrix();
  }
}

class ServeOrientation : public ::testing::Test {
 protected:
  void SetUp() override {
    RegisterOptions options;
    options.interpolation.method = InterpolationMethod::kKriging;
    model_ = register_fiducials(cell_, options).model;
    io::write_model_json(dir_.file("cell.json"), model_);
    model_ = io::read_model_json(dir_.file("cell.json"));
  }
  MeasurementSet cell_ = vrreg::testing::cell_with_orientations();
  TempDir dir_;
  RegistrationModel model_;
};

TEST_F(ServeOrientation, PoseRequestsAreAnsweredAsCorrectInTheFormAsked) {
  Service service(local_options(dir_.file("cell.json")), nullptr);
  service.start();
  LineClient c(service.line_port());
  int answered = 0;
  for (const std::size_t t : cell_.select(Role::kTarget)) {
    const Location& target = cell_.locations[t];
    MeasuredPoints p;
    p.sensor_m = target.sensor_m;
    p.q_sensor_marker = {*target.q_sensor_marker};
    const CorrectResult r = correct(model_, p);
    for (const OrientationForm form :
         {OrientationForm::kQuaternion, OrientationForm::kRotationVector,
          OrientationForm::kKukaAbc}) {
      const std::string line = pose_line(target, form);
      const std::string reply = c.ask(line);
      ASSERT_EQ(reply, expected_pose_reply(model_, line)) << line;
      const std::vector<double> v = numbers_of(reply);
      ASSERT_EQ(v.size(), 5u + static_cast<std::size_t>(orientation_numbers(form))) << reply;
      // Whatever the form, the orientation to command is the library's, to the printed digits.
      EXPECT_LT(
          rotation_angle_rad(orientation_of(v, form), r.orientation->corrected_R_robot_marker[0]),
          1e-9)
          << reply;
      EXPECT_NEAR(v.back(), 1e3 * r.orientation->predicted_sd_rad(0), 1e-9);
      EXPECT_GT(v.back(), 0.0);
      ++answered;
    }
  }
  EXPECT_EQ(answered, 3 * 64);
  // Without the orientation the same point is answered as before: position and sd only.
  const Location& first = cell_.locations[cell_.select(Role::kTarget).front()];
  const std::string point = pose_line(first, OrientationForm::kQuaternion);
  EXPECT_EQ(c.ask(point.substr(0, point.find(" quat")) + "\n"),
            expected_reply(model_, units::m_to_mm(1.0) * first.sensor_m));
}

// Whatever the method, a model with orientations is served (its load-time probe is an
// extrapolating pose request) and answers poses inside and beyond its support as `correct` does.
TEST_F(ServeOrientation, EveryMethodServesPosesInsideAndExtrapolated) {
  int answered = 0;
  for (const InterpolationMethod method :
       {InterpolationMethod::kGrid, InterpolationMethod::kScattered, InterpolationMethod::kTrilinear,
        InterpolationMethod::kKriging, InterpolationMethod::kRbf}) {
    SCOPED_TRACE(to_string(method));
    RegisterOptions options;
    options.interpolation.method = method;
    const std::string path = dir_.file(std::string(to_string(method)) + ".json");
    io::write_model_json(path, register_fiducials(cell_, options).model);
    const RegistrationModel model = io::read_model_json(path);
    Service service(local_options(path), nullptr);
    ASSERT_NO_THROW(service.start());
    LineClient c(service.line_port());
    Location target = cell_.locations[cell_.select(Role::kTarget)[7]];
    for (const bool beyond : {false, true}) {
      // Beyond: 0.2 m along the sensor's x from a target, outside the fiducials' box.
      if (beyond) target.sensor_m.x() += 0.2;
      std::string line = pose_line(target, OrientationForm::kQuaternion);
      if (beyond) line.insert(line.size() - 1, " extrapolate");
      MeasuredPoints p;
      p.sensor_m = target.sensor_m;
      p.q_sensor_marker = {*target.q_sensor_marker};
      CorrectOptions o;
      o.extrapolate = beyond;
      const CorrectResult r = correct(model, p, o);
      const StencilStatus status = r.correction.stencils[0].status;
      const std::vector<double> v = numbers_of(c.ask(line));
      ASSERT_EQ(v.size(), 9u) << line;
      if (r.correction.guard && !r.correction.guard->applied) {  // its guard held it back
        EXPECT_EQ(v[7], -3.0);
        continue;
      }
      ASSERT_EQ(status, beyond ? StencilStatus::kExtrapolated : StencilStatus::kOk);
      if (!is_corrected(r.orientation->status[0])) {  // the pose is refused as a whole
        EXPECT_LT(v[7], 0.0) << to_string(r.orientation->status[0]);
        continue;
      }
      ++answered;
      for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(v[static_cast<std::size_t>(a)],
                    units::m_to_mm(r.correction.corrected_robot_m(a, 0)), 1e-6);
      }
      EXPECT_LT(rotation_angle_rad(orientation_of(v, OrientationForm::kQuaternion),
                                   r.orientation->corrected_R_robot_marker[0]),
                1e-8);
      EXPECT_GE(v[7], 0.0);
      EXPECT_GE(v[8], 0.0);
      // An extrapolated answer always carries its sd, the stencils' too.
      if (beyond) {
        EXPECT_GT(v[7], 0.0);
      }
    }
  }
  EXPECT_GE(answered, 7);  // at most one method held back by its guard on this cell
}

TEST_F(ServeOrientation, BadOrientationsAreRefusedInTheFormTheClientReads) {
  Service service(local_options(dir_.file("cell.json")), nullptr);
  service.start();
  LineClient c(service.line_port());
  EXPECT_EQ(c.ask("cell 500 0 2000 rotvec 1 2\n"), "(0,0,0,0,0,0,-1,-1)\n");
  EXPECT_EQ(c.ask("cell 500 0 2000 quat 1 1 1 1\n"), "(0,0,0,0,0,0,0,-1,-1)\n");
  EXPECT_EQ(c.ask("cell 500 0 2000 abc 0 nan 0\n"), "(0,0,0,0,0,0,-1,-1)\n");
  EXPECT_EQ(c.ask("cell 500 0 2000 rotvec 0 0 0 abc 0 0 0\n"), "(0,0,0,0,0,0,-1,-1)\n");
  EXPECT_EQ(c.ask("cell 1e5 0 0 abc 0 0 0\n"), "(0,0,0,0,0,0,-3,-3)\n");
  EXPECT_EQ(c.ask("nope 1 2 3 rotvec 0 0 0\n"), "(0,0,0,0,0,0,-2,-2)\n");

  // A model of positions only: a pose request says so (code 4), in the pose's form.
  MeasurementSet positions_only = cell_;
  for (Location& l : positions_only.locations) l.q_robot_marker.reset();
  RegisterOptions options;
  options.interpolation.method = InterpolationMethod::kKriging;
  io::write_model_json(dir_.file("points.json"), register_fiducials(positions_only, options).model);
  ServeOptions o = local_options(dir_.file("points.json"));
  Service points(o, nullptr);
  points.start();
  LineClient p(points.line_port());
  const Location& target = cell_.locations[cell_.select(Role::kTarget).front()];
  EXPECT_EQ(p.ask(pose_line(target, OrientationForm::kRotationVector)), "(0,0,0,0,0,0,-4,-4)\n");
  const std::string http =
      http_request(points.http_port(), "POST", "/v1/correct",
                   R"({"model":"cell","sensor_mm":[500,0,2000],"sensor_q":[0,0,0,1]})");
  EXPECT_THAT(http, StartsWith("422 "));
  EXPECT_THAT(http, HasSubstr("corrects positions only"));
}

TEST_F(ServeOrientation, HttpCarriesTheQuaternionBothWays) {
  Service service(local_options(dir_.file("cell.json")), nullptr);
  service.start();
  const Location& target = cell_.locations[cell_.select(Role::kTarget)[5]];
  const Eigen::Quaterniond& q = *target.q_sensor_marker;
  const Eigen::Vector3d mm = units::m_to_mm(1.0) * target.sensor_m;
  const nlohmann::json body = {{"model", "cell"},
                               {"sensor_mm", {mm.x(), mm.y(), mm.z()}},
                               {"sensor_q", {q.x(), q.y(), q.z(), q.w()}}};
  const std::string reply = http_request(service.http_port(), "POST", "/v1/correct", body.dump());
  ASSERT_THAT(reply, StartsWith("200 "));
  const nlohmann::json j = nlohmann::json::parse(reply.substr(4));
  MeasuredPoints p;
  p.sensor_m = mm / units::kMillimetresPerMetre;
  p.q_sensor_marker = {q};
  const CorrectResult r = correct(model_, p);
  const auto& rq = j["robot_q"];
  const Eigen::Quaterniond got(rq[3].get<double>(), rq[0].get<double>(), rq[1].get<double>(),
                               rq[2].get<double>());
  EXPECT_GE(got.w(), 0.0);
  EXPECT_LT(rotation_angle_rad(got.toRotationMatrix(), r.orientation->corrected_R_robot_marker[0]),
            1e-14);
  EXPECT_EQ(j["predicted_angle_sd_mrad"].get<double>(), 1e3 * r.orientation->predicted_sd_rad(0));
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(j["rotation_applied_mrad"][a].get<double>(),
              1e3 * r.orientation->corrections_robot_rad(a, 0));
  }
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct",
                           R"({"model":"cell","sensor_mm":[500,0,2000],"sensor_q":[0,0,1]})"),
              StartsWith("400 "));
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct",
                           R"({"model":"cell","sensor_mm":[500,0,2000],"sensor_q":[0,0,2,1]})"),
              StartsWith("400 "));
  const std::string health = http_request(service.http_port(), "GET", "/v1/health", "");
  EXPECT_THAT(health, HasSubstr("\"corrects_orientation\":true"));
}

TEST_F(ServeOrientation, SnippetPoseRequestsAreAnswered) {
  Service service(local_options(dir_.file("cell.json")), nullptr);
  service.start();
  SnippetOptions s;
  s.model = "cell";
  s.port = service.line_port();
  const std::string urscript = urscript_client(s);
  EXPECT_THAT(urscript, HasSubstr("def vrreg_correct_pose(p_sensor_mm):"));
  EXPECT_THAT(urscript, HasSubstr("reply = vrreg_ask("));
  EXPECT_THAT(urscript, HasSubstr(", 8)\n  if reply[7] < 0:"));
  EXPECT_THAT(urscript, HasSubstr("str_cat(\" rotvec \", vrreg_text(p_sensor_mm[3], 10000000))"));
  EXPECT_THAT(urscript,
              HasSubstr("return p[r[0] / 1000, r[1] / 1000, r[2] / 1000, r[3], r[4], r[5]]"));
  const std::string krl = krl_pose_client(s);
  EXPECT_THAT(krl, HasSubstr("DEFFCT BOOL VRREG_CORRECT_POSE(P_SENSOR_MM:IN, P_ROBOT_MM:OUT, "
                             "SD_MM:OUT, SD_MRAD:OUT)"));
  EXPECT_THAT(krl, HasSubstr("\"cell %.6f %.6f %.6f abc %.6f %.6f %.6f%c\""));
  EXPECT_THAT(krl, HasSubstr("\"(%r,%r,%r,%r,%r,%r,%r,%r)\""));
  EXPECT_THAT(krl_client(s), HasSubstr("\"cell %.6f %.6f %.6f%c\""));

  LineClient c(service.line_port());
  const Location& target = cell_.locations[cell_.select(Role::kTarget)[9]];
  const Eigen::Vector3d mm = units::m_to_mm(1.0) * target.sensor_m;
  const Eigen::Matrix3d R = target.q_sensor_marker->toRotationMatrix();
  // The program's vrreg_text: mm to 4 decimals, the rotation vector to 7.
  const Eigen::Vector3d w = rotation_log(R);
  std::array<std::string, 6> pose;
  for (int a = 0; a < 3; ++a) {
    pose[static_cast<std::size_t>(a)] =
        vrreg::testing::urscript_vrreg_text(static_cast<float>(mm(a)), 10000);
    pose[static_cast<std::size_t>(a) + 3] =
        vrreg::testing::urscript_vrreg_text(static_cast<float>(w(a)), 10000000);
  }
  const std::string ur_line = urscript_pose_request_line(s, pose);
  EXPECT_THAT(ur_line, HasSubstr(" rotvec "));
  const std::string ur_reply = c.ask(ur_line);
  EXPECT_EQ(ur_reply, expected_pose_reply(model_, ur_line));
  EXPECT_EQ(numbers_of(ur_reply).size(), 8u);
  // KRL's SWRITE "%.6f", the FRAME's A, B, C in degrees.
  const Eigen::Vector3d abc = kuka_abc_deg(R);
  const std::string krl_line =
      krl_request_line(s, {mm.x(), mm.y(), mm.z(), abc(0), abc(1), abc(2)}, true);
  const std::string krl_reply = c.ask(krl_line);
  EXPECT_EQ(krl_reply, expected_pose_reply(model_, krl_line));
  EXPECT_EQ(numbers_of(krl_reply).size(), 8u);
  const std::string krl_point = krl_request_line(s, {mm.x(), mm.y(), mm.z(), 0, 0, 0}, false);
  EXPECT_EQ(numbers_of(c.ask(krl_point)).size(), 4u);
}

}  // namespace
}  // namespace vrreg::serve::testing
