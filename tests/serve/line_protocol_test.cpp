// SPDX-License-Identifier: Apache-2.0
#include "serve/line_protocol.hpp"

#include <gtest/gtest.h>

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
        "cell 1 2 3 \xff", std::string(65, 'm') + " 1 2 3", "auth", "auth a b"}) {
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
}

}  // namespace
}  // namespace vrreg::serve
