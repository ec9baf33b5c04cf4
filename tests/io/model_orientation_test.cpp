// SPDX-License-Identifier: Apache-2.0
// A model with rigid-body orientations through its file: the fiducials' orientations and the
// fitted orientation field are written and read back to the bit, so the model read corrects
// orientations exactly as the one written; a field that does not fit its fiducials is an error
// naming the key.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "orientation_cell.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::io {
namespace {

using vrreg::testing::cell_with_orientations;

TEST(ModelOrientation, FieldAndFiducialOrientationsRoundTripToTheBit) {
  const MeasurementSet set = cell_with_orientations();
  RegisterOptions options;
  options.interpolation.method = InterpolationMethod::kScattered;
  const RegistrationModel model = register_fiducials(set, options).model;
  ASSERT_TRUE(model.orientation_corrector.has_value());
  const RegistrationModel read = parse_model_json(format_model_json(model), "cell.json");
  ASSERT_TRUE(read.orientation_corrector.has_value());
  for (std::size_t j = 0; j < model.fiducials.size(); ++j) {
    EXPECT_EQ(read.fiducials[j].q_sensor_marker->coeffs(),
              model.fiducials[j].q_sensor_marker->coeffs());
    EXPECT_EQ(read.fiducials[j].q_robot_marker->coeffs(),
              model.fiducials[j].q_robot_marker->coeffs());
    EXPECT_EQ(read.fiducials[j].orientation_sq_dev_rad2,
              model.fiducials[j].orientation_sq_dev_rad2);
  }
  const EvaluateResult a = evaluate(model, set);
  const EvaluateResult b = evaluate(read, set);
  ASSERT_TRUE(a.orientation && b.orientation);
  EXPECT_EQ(a.orientation->cor_error_rad, b.orientation->cor_error_rad);
  EXPECT_EQ(a.orientation->correction.predicted_sd_rad, b.orientation->correction.predicted_sd_rad);
  EXPECT_LT(a.orientation->cor_rms_rad, 0.3 * a.orientation->unc_rms_rad);
  // A file without the field corrects orientations too (fitted when used), with the same bits.
  nlohmann::json doc = nlohmann::json::parse(format_model_json(model));
  doc.erase("orientation_corrector");
  const RegistrationModel without = parse_model_json(doc.dump(), "cell.json");
  EXPECT_EQ(evaluate(without, set, {.refit = true}).orientation->cor_error_rad,
            a.orientation->cor_error_rad);
}

TEST(ModelOrientation, FieldWithoutFiducialOrientationsIsAnErrorNamingTheKey) {
  const MeasurementSet set = cell_with_orientations();
  RegisterOptions options;
  options.interpolation.method = InterpolationMethod::kScattered;
  nlohmann::json doc =
      nlohmann::json::parse(format_model_json(register_fiducials(set, options).model));
  for (nlohmann::json& f : doc["fiducials"]) f.erase("q_robot_marker");
  try {
    (void)parse_model_json(doc.dump(), "cell.json");
    FAIL() << "read a field without its fiducials' orientations";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("orientation_corrector"), std::string::npos) << e.what();
  }
  doc = nlohmann::json::parse(format_model_json(register_fiducials(set, options).model));
  doc["fiducials"][0]["q_sensor_marker"] = {0.0, 0.0, 0.0, 2.0};
  EXPECT_THROW((void)parse_model_json(doc.dump(), "cell.json"), FileError);
}

}  // namespace
}  // namespace vrreg::io
