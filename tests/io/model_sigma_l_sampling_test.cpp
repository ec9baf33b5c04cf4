// SPDX-License-Identifier: Apache-2.0
// A sampled sigma_L says so in the model file (rigid_body_sampled.hpp), and reads back.
#include <gtest/gtest.h>

#include <string>

#include "io_test_helpers.hpp"
#include "vrreg/io/model_json.hpp"

namespace vrreg::io {
namespace {

RegistrationModel small_model() {
  RegistrationModel m;
  m.sigma_l_m = 1.25e-4;
  m.source = "f.csv";
  m.corrections_sensor_m = Points3::Zero(3, 3);
  for (int j = 0; j < 3; ++j) {
    Location f;
    f.point = "F" + std::to_string(j);
    f.robot_m = Eigen::Vector3d(0.1 * j, 0.2, 0.3);
    f.sensor_m = f.robot_m;
    f.n_readings = 1;
    m.fiducials.push_back(f);
  }
  return m;
}

TEST(ModelSigmaLSampling, ExactModelsHaveNoKey) {
  EXPECT_EQ(format_model_json(small_model()).find("sigma_l_sampling"), std::string::npos);
  EXPECT_FALSE(
      parse_model_json(format_model_json(small_model()), "m.json").sigma_l_sampling.sampled);
}

TEST(ModelSigmaLSampling, SampledModelsSaySoAndReadBack) {
  RegistrationModel m = small_model();
  m.sigma_l_sampling.sampled = true;
  m.sigma_l_sampling.pairs_sampled = 10000000;
  m.sigma_l_sampling.pairs_total = 499999500000;
  m.sigma_l_sampling.seed = 18446744073709551615ULL;
  m.sigma_l_sampling.sigma_l_low_m = 1.2e-4;
  m.sigma_l_sampling.sigma_l_high_m = 1.3e-4;
  const std::string text = format_model_json(m);
  EXPECT_NE(text.find("\"sigma_l_sampling\""), std::string::npos) << text;
  const RegistrationModel r = parse_model_json(text, "m.json");
  EXPECT_TRUE(r.sigma_l_sampling.sampled);
  EXPECT_EQ(r.sigma_l_sampling.pairs_sampled, 10000000);
  EXPECT_EQ(r.sigma_l_sampling.pairs_total, 499999500000);
  EXPECT_EQ(r.sigma_l_sampling.seed, 18446744073709551615ULL);
  EXPECT_DOUBLE_EQ(r.sigma_l_sampling.confidence, 0.95);
  EXPECT_NEAR(r.sigma_l_sampling.sigma_l_low_m, 1.2e-4, 1e-18);
  EXPECT_NEAR(r.sigma_l_sampling.sigma_l_high_m, 1.3e-4, 1e-18);
  EXPECT_EQ(format_model_json(r), text);
}

TEST(ModelSigmaLSampling, BadValuesNameTheKey) {
  RegistrationModel m = small_model();
  m.sigma_l_sampling = {true, 100, 200, 1, 0.95, 1e-4, 2e-4};
  const std::string good = format_model_json(m);
  const auto fails_with = [&](const std::string& from, const std::string& to,
                              const std::string& words) {
    std::string bad = good;
    const auto at = bad.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    bad.replace(at, from.size(), to);
    EXPECT_TRUE(vrreg::testing::throws_file_error([&] { (void)parse_model_json(bad, "m.json"); },
                                                  "m.json", 0, words));
  };
  fails_with("\"pairs\": 100", "\"pairs\": 1.5", "sigma_l_sampling.pairs");
  fails_with("\"seed\": 1", "\"seed\": -1", "sigma_l_sampling.seed");
  fails_with("\"confidence\": 0.95", "\"confidence\": 1.5", "sigma_l_sampling.confidence");
  fails_with("\"interval_m\": [", "\"interval_m\": [1, ", "sigma_l_sampling.interval_m");
}

}  // namespace
}  // namespace vrreg::io
