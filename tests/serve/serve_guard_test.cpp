// SPDX-License-Identifier: Apache-2.0
// A model whose correction is not better than none (its guard): the service answers every point
// with code 3 and the uncorrected position, the status saying why, on both protocols.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include <nlohmann/json.hpp>

#include "serve/service.hpp"
#include "serve_test_support.hpp"
#include "vrreg/core/format.hpp"

namespace vrreg::serve::testing {
namespace {

using ::testing::HasSubstr;

TEST(ServeGuard, ACorrectionNotBetterThanNoneIsRefusedWithTheUncorrectedPosition) {
  // The lattice cell without its robot error: what is left is the readings' noise.
  MeasuredPoints cell = lattice_cell();
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 2e-5);
  for (Eigen::Index j = 0; j < cell.size(); ++j)
    for (int a = 0; a < 3; ++a) cell.sensor_m(a, j) = cell.robot_m(a, j) + noise(rng);
  RegisterOptions options;
  options.interpolation.method = InterpolationMethod::kKriging;
  const RegistrationModel model = register_fiducials(cell, options).model;
  ASSERT_TRUE(model.corrector && model.corrector->guard());
  ASSERT_FALSE(model.corrector->applied());
  TempDir dir;
  io::write_model_json(dir.file("noise.json"), model);
  ServeOptions o;
  o.models = {{"cell", dir.file("noise.json")}};
  o.line = Endpoint{"127.0.0.1", 0};
  o.http = Endpoint{"127.0.0.1", 0};
  o.threads = 2;
  o.reload_poll_ms = 0;
  Service service(o, nullptr);
  service.start();
  const Eigen::Vector3d p_mm = 1e3 * cell.sensor_m.col(62);  // an interior fiducial
  LineClient client(service.line_port());
  EXPECT_EQ(client.ask("cell " + format_general(p_mm.x(), 17) + " " + format_general(p_mm.y(), 17) +
                       " " + format_general(p_mm.z(), 17) + "\n"),
            "(0,0,0,-3)\n");
  const nlohmann::json request = {{"model", "cell"}, {"sensor_mm", {p_mm.x(), p_mm.y(), p_mm.z()}}};
  const std::string reply =
      http_request(service.http_port(), "POST", "/v1/correct", request.dump());
  ASSERT_THAT(reply, ::testing::StartsWith("422 "));  // a refusal of the point, not of the request
  const nlohmann::json j = nlohmann::json::parse(reply.substr(4));
  EXPECT_EQ(j.at("code"), 3);
  EXPECT_EQ(j.at("status"), "correction not better than none");
  EXPECT_THAT(j.at("error").get<std::string>(), HasSubstr("correction not better than none"));
  EXPECT_THAT(j.at("error").get<std::string>(), ::testing::Not(HasSubstr("extrapolate")));
  MeasuredPoints point;
  point.sensor_m = cell.sensor_m.col(62);
  const TargetCorrection c = correct(model, point).correction;
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(j.at("uncorrected_robot_mm")[a].get<double>(),
                     units::m_to_mm(c.uncorrected_robot_m(a, 0)));
  }
}

}  // namespace
}  // namespace vrreg::serve::testing
