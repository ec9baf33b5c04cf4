// SPDX-License-Identifier: Apache-2.0
// The model file's Procedure 2 block (paper section 4.4): round trip, absent for plain models,
// and clear errors for a broken block.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io_test_helpers.hpp"
#include "vrreg/io/model_json.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::throws_file_error;

RegistrationModel model_with_fiducials(int n) {
  RegistrationModel m;
  m.source = "cell.csv";
  m.corrections_sensor_m = Points3::Zero(3, n);
  for (int j = 0; j < n; ++j) {
    Location f;
    f.point = "F" + std::to_string(j);
    f.config = 1 + j % 2;
    f.q_rad = {0.1 * j, -0.2};
    f.n_readings = 1;
    m.fiducials.push_back(f);
  }
  return m;
}

TEST(ModelProcedure2, Strategy3RoundTrips) {
  RegistrationModel m = model_with_fiducials(10);
  m.procedure2.strategy = planning::Strategy::kVolumeCorners;
  m.procedure2.joint_norm = kinematics::JointNorm::kLinf;
  m.procedure2.seed = 18446744073709551615ULL;
  m.procedure2.registration_fiducials = {0, 3, 2, 5, 4, 7, 6, 9};
  const RegistrationModel back = parse_model_json(format_model_json(m), "m.json");
  EXPECT_EQ(back.procedure2.strategy, planning::Strategy::kVolumeCorners);
  EXPECT_EQ(back.procedure2.joint_norm, kinematics::JointNorm::kLinf);
  EXPECT_EQ(back.procedure2.seed, m.procedure2.seed);
  EXPECT_EQ(back.procedure2.registration_fiducials, m.procedure2.registration_fiducials);
  EXPECT_EQ(back.fiducials[3].config, 2);
}

TEST(ModelProcedure2, Strategy2RoundTripsAndPlainModelsHaveNoBlock) {
  RegistrationModel m = model_with_fiducials(3);
  EXPECT_EQ(format_model_json(m).find("procedure2"), std::string::npos);
  EXPECT_EQ(parse_model_json(format_model_json(m), "m.json").procedure2.strategy,
            planning::Strategy::kNone);
  m.procedure2.strategy = planning::Strategy::kAlongPath;
  const RegistrationModel back = parse_model_json(format_model_json(m), "m.json");
  EXPECT_EQ(back.procedure2.strategy, planning::Strategy::kAlongPath);
  EXPECT_EQ(back.procedure2.joint_norm, kinematics::JointNorm::kL2);
  EXPECT_FALSE(back.procedure2.seed);
  EXPECT_TRUE(back.procedure2.registration_fiducials.empty());
}

TEST(ModelProcedure2, BrokenBlockNamesTheKey) {
  RegistrationModel m = model_with_fiducials(3);
  m.procedure2.strategy = planning::Strategy::kVolumeCorners;
  m.procedure2.seed = 1;
  m.procedure2.registration_fiducials = {0, 1, 2};
  const nlohmann::json good = nlohmann::json::parse(format_model_json(m));
  const auto broken = [&](const std::string& key, const nlohmann::json& value) {
    nlohmann::json doc = good;
    doc["procedure2"][key] = value;
    return doc.dump();
  };
  EXPECT_TRUE(throws_file_error([&] { parse_model_json(broken("strategy", 4), "m.json"); },
                                "m.json", 0, "procedure2.strategy"));
  EXPECT_TRUE(throws_file_error([&] { parse_model_json(broken("joint_norm", "l1"), "m.json"); },
                                "m.json", 0, "procedure2.joint_norm"));
  EXPECT_TRUE(throws_file_error([&] { parse_model_json(broken("seed", -1), "m.json"); }, "m.json",
                                0, "procedure2.seed"));
  EXPECT_TRUE(throws_file_error(
      [&] {
        parse_model_json(broken("registration_fiducials", {0, 3}), "m.json");
      },
      "m.json", 0, "procedure2.registration_fiducials"));
  m.procedure2.registration_fiducials = {5};
  EXPECT_THROW(format_model_json(m), InputError);
}

}  // namespace
}  // namespace vrreg::io
