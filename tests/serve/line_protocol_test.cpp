// SPDX-License-Identifier: Apache-2.0
#include "serve/line_protocol.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "serve/http_api.hpp"

namespace vrreg::serve {
namespace {

TEST(LineProtocol, ReadsAPointWithItsOptions) {
  const LineRequest r = parse_line_request("cell 412.5,-90\t3.1e2 config 2 joints 0.1 -0.2 0.3 extrapolate\r");
  ASSERT_TRUE(std::holds_alternative<PointRequest>(r));
  const auto& p = std::get<PointRequest>(r);
  EXPECT_EQ(p.model, "cell");
  EXPECT_EQ(p.sensor_mm, Eigen::Vector3d(412.5, -90, 310));
  EXPECT_EQ(p.config, 2);
  EXPECT_EQ(p.joints_rad, (std::vector<double>{0.1, -0.2, 0.3}));
  EXPECT_TRUE(p.extrapolate);
  EXPECT_EQ(std::get<PointRequest>(parse_line_request("c +1 2 3")).sensor_mm.x(), 1.0);
}

TEST(LineProtocol, RefusesWhatIsNotARequest) {
  for (const std::string& line : std::vector<std::string>{"", "   ", "cell", "cell 1 2", "cell 1 2 x", "cell nan 1 2", "cell inf 1 2", "cell 1e10 0 0",
        "cell 1 2 3 config", "cell 1 2 3 config 1.5", "cell 1 2 3 joints", "cell 1 2 3 joints x",
        "cell 1 2 3 extrapolate extrapolate", "cell 1 2 3 4", "ce/ll 1 2 3", "cell 1 2 3\x01",
        "cell 1 2 3 \xff", std::string(65, 'm') + " 1 2 3", "auth", "auth a b",
        "cell +-767.2 1 2", "cell 1 ++2 3", "cell 1 2 3 joints +-0.1"}) {
    const LineRequest r = parse_line_request(line);
    ASSERT_TRUE(std::holds_alternative<BadRequest>(r)) << line;
    EXPECT_FALSE(std::get<BadRequest>(r).reason.empty());
  }
}

TEST(LineProtocol, RepliesAsSocketReadAsciiFloatReads) {
  PointAnswer a;
  a.robot_mm = Eigen::Vector3d(412.123456789012345, -90.0, 1e-7);
  a.sd_mm = 0.0421;
  EXPECT_EQ(format_line_reply(a), "(412.123456789,-90,0.000000100000000,0.0421)\n");
  EXPECT_EQ(format_line_reply(PointAnswer::refusal(ReplyCode::kNotCorrectable, "x")), "(0,0,0,-3)\n");
  EXPECT_EQ(line_auth_accepted(), "(1)\n");
}

TEST(LineProtocol, ReadsTheMarkersOrientationInThreeForms) {
  const auto q_of = [](const std::string& line) {
    const LineRequest r = parse_line_request(line);
    EXPECT_TRUE(std::holds_alternative<PointRequest>(r)) << line;
    return std::get<PointRequest>(r);
  };
  // A quarter turn about z, three ways: the same unit quaternion.
  const double s = std::sqrt(0.5);
  const PointRequest quat = q_of("cell 1 2 3 quat 0 0 0.70710678118654757 0.70710678118654757");
  const PointRequest rotvec = q_of("cell 1 2 3 ROTVEC 0,0,1.5707963267948966 extrapolate");
  const PointRequest abc = q_of("cell 1 2 3 joints 0.1 0.2 abc 90 0 0");
  EXPECT_EQ(quat.orientation_form, OrientationForm::kQuaternion);
  EXPECT_EQ(rotvec.orientation_form, OrientationForm::kRotationVector);
  EXPECT_EQ(abc.orientation_form, OrientationForm::kKukaAbc);
  EXPECT_EQ(abc.joints_rad.size(), 2u);
  EXPECT_TRUE(rotvec.extrapolate);
  for (const PointRequest* r : {&quat, &rotvec, &abc}) {
    ASSERT_TRUE(r->q_sensor_marker.has_value());
    EXPECT_LT(r->q_sensor_marker->angularDistance(Eigen::Quaterniond(s, 0, 0, s)), 1e-15);
  }
  EXPECT_FALSE(q_of("cell 1 2 3").q_sensor_marker.has_value());
  for (const std::string& line : std::vector<std::string>{
           "cell 1 2 3 rotvec", "cell 1 2 3 rotvec 1 2", "cell 1 2 3 rotvec 1 2 x",
           "cell 1 2 3 rotvec 1 2 1000", "cell 1 2 3 quat 0 0 0 2", "cell 1 2 3 quat 0 0 0",
           "cell 1 2 3 abc 0 0 nan", "cell 1 2 3 abc 0 0 0 quat 0 0 0 1",
           "cell 1 2 3 rotvec 0 0 0 rotvec 0 0 0"}) {
    const LineRequest r = parse_line_request(line);
    ASSERT_TRUE(std::holds_alternative<BadRequest>(r)) << line;
    EXPECT_NE(std::get<BadRequest>(r).form, OrientationForm::kNone) << line;
  }
}

TEST(LineProtocol, RepliesWithTheOrientationInTheRequestsForm) {
  PointAnswer a;
  a.robot_mm = Eigen::Vector3d(412.5, -90.0, 310.0);
  a.sd_mm = 0.0421;
  a.angle_sd_rad = 0.00061;
  a.q_robot_marker = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  EXPECT_EQ(format_line_reply(a, OrientationForm::kRotationVector),
            "(412.5,-90,310,0,0,1.57079632679,0.0421,0.61)\n");
  EXPECT_EQ(format_line_reply(a, OrientationForm::kKukaAbc),
            "(412.5,-90,310,90,0,0,0.0421,0.61)\n");
  a.q_robot_marker->coeffs() *= -1.0;  // the same orientation: answered with w >= 0
  EXPECT_EQ(format_line_reply(a, OrientationForm::kQuaternion),
            "(412.5,-90,310,0,0,0.707106781187,0.707106781187,0.0421,0.61)\n");
  EXPECT_EQ(format_line_reply(a), "(412.5,-90,310,0.0421)\n");
  const PointAnswer refused = PointAnswer::refusal(ReplyCode::kInput, "x");
  EXPECT_EQ(format_line_reply(refused, OrientationForm::kKukaAbc), "(0,0,0,0,0,0,-4,-4)\n");
  EXPECT_EQ(format_line_reply(refused, OrientationForm::kQuaternion), "(0,0,0,0,0,0,0,-4,-4)\n");
}

TEST(HttpApi, ReadsOnePointOrABatchAndRefusesTheRest) {
  auto one = parse_http_correct(R"({"model":"c","sensor_mm":[1,2,3],"joints_rad":[0.5],"config":3})", 10);
  ASSERT_TRUE(std::holds_alternative<HttpCorrectRequest>(one));
  EXPECT_FALSE(std::get<HttpCorrectRequest>(one).batch);
  EXPECT_EQ(std::get<HttpCorrectRequest>(one).points[0].config, 3);
  auto batch = parse_http_correct(R"({"model":"c","extrapolate":true,"points":[{"sensor_mm":[1,2,3]},{"sensor_mm":[4,5,6]}]})", 10);
  ASSERT_TRUE(std::holds_alternative<HttpCorrectRequest>(batch));
  EXPECT_EQ(std::get<HttpCorrectRequest>(batch).points.size(), 2u);
  EXPECT_TRUE(std::get<HttpCorrectRequest>(batch).points[1].extrapolate);
  const auto code = [](std::string_view body) {
    const auto r = parse_http_correct(body, 1);
    return std::holds_alternative<PointAnswer>(r) ? static_cast<int>(std::get<PointAnswer>(r).code) : 0;
  };
  EXPECT_EQ(code("not json"), 1);
  EXPECT_EQ(code("[]"), 1);
  EXPECT_EQ(code(R"({"sensor_mm":[1,2,3]})"), 1);
  EXPECT_EQ(code(R"({"model":"c","sensor_mm":[1,2]})"), 1);
  EXPECT_EQ(code(R"({"model":"c","sensor_mm":[1,2,"3"]})"), 1);
  EXPECT_EQ(code(R"({"model":"c","sensor_mm":[1,2,3],"extra":1})"), 1);
  EXPECT_EQ(code(R"({"model":"c","sensor_mm":[1,2,1e300]})"), 1);
  EXPECT_EQ(code(R"({"model":"c","points":[{"sensor_mm":[1,2,3]},{"sensor_mm":[1,2,3]}]})"), 6);
  EXPECT_EQ(code(std::string(100, '[') + std::string(100, ']')), 1);
  // An empty batch is refused before any handler reads its first point.
  EXPECT_EQ(code(R"({"model":"c","points":[]})"), 1);
  // A batch refuses unknown top-level keys as a single request does.
  EXPECT_EQ(code(R"({"model":"c","points":[{"sensor_mm":[1,2,3]}],"sensor_q":[0,0,0,1]})"), 1);
  EXPECT_EQ(code(R"({"model":"c","points":[{"sensor_mm":[1,2,3]}],"extra":1})"), 1);
}

}  // namespace
}  // namespace vrreg::serve
