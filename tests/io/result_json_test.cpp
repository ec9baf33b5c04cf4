// SPDX-License-Identifier: Apache-2.0
// The one place where results become JSON and a brief report: the figures are the result's (in
// mm), the summary is over the corrected targets only, and fmt / iostream print the brief report.
#include "vrreg/io/result_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "vrreg/io/result_format.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::io {
namespace {

// 27 fiducials on a 3 x 3 x 3 lattice at 50 mm, a smooth sensor distortion; targets: two inside,
// one 1 m away (outside every method's support).
struct ResultCell {
  MeasuredPoints fiducials, targets;
  ResultCell() {
    const auto read = [](const Eigen::Vector3d& y) {
      return Eigen::Vector3d(y + Eigen::Vector3d(-1.0, 0.2, 0.1) +
                             1e-4 * Eigen::Vector3d(std::sin(20 * y.x()), y.y(), y.z() * y.z()));
    };
    fiducials.robot_m.resize(3, 27);
    fiducials.sensor_m.resize(3, 27);
    for (int i = 0; i < 27; ++i) {
      fiducials.robot_m.col(i) =
          Eigen::Vector3d(0.4, -0.1, 0.3) + 0.05 * Eigen::Vector3d(i % 3, i / 3 % 3, i / 9);
      fiducials.sensor_m.col(i) = read(fiducials.robot_m.col(i));
    }
    targets.robot_m.resize(3, 3);
    targets.robot_m << 0.42, 0.47, 1.4,  //
        -0.08, -0.03, -0.1,              //
        0.33, 0.36, 0.3;
    targets.sensor_m.resize(3, 3);
    for (int t = 0; t < 3; ++t) targets.sensor_m.col(t) = read(targets.robot_m.col(t));
    targets.names = {"A", "B", "FAR"};
  }
};

TEST(ResultJson, EvaluateGivesTheCorrectedFiguresAndTheFlaggedApart) {
  const ResultCell cell;
  const RegisterResult r = register_fiducials(cell.fiducials);
  EvaluateOptions options;
  options.interpolation.method = InterpolationMethod::kScattered;
  const EvaluateResult e = evaluate(r.model, cell.targets, options);
  ASSERT_EQ(e.correction.n_flagged, 1);
  const nlohmann::json j = evaluate_json(e, r.model);
  EXPECT_EQ(j["n_targets"], 3);
  EXPECT_EQ(j["n_corrected"], 2);
  EXPECT_EQ(j["n_flagged"], 1);
  EXPECT_DOUBLE_EQ(j["flagged_rms_t_mm"].get<double>(), 1e3 * e.unc_tre_m(2));
  EXPECT_DOUBLE_EQ(j["cor_rms_t_mm"].get<double>(),
                   1e3 * std::sqrt(e.cor_tre_m.head(2).squaredNorm() / 2));
  EXPECT_DOUBLE_EQ(j["unc_max_tre_mm"].get<double>(), 1e3 * e.unc_tre_m.head(2).maxCoeff());
  EXPECT_EQ(j["interpolation"], "scattered");
  EXPECT_TRUE(j["strategy"].is_null());

  const std::string brief = brief_report(e);
  EXPECT_NE(brief.find("3 targets, scattered: RMS_T "), std::string::npos) << brief;
  EXPECT_NE(brief.find("n_flagged 1 (RMS_T "), std::string::npos) << brief;
  EXPECT_EQ(fmt::format("{}", e), brief);
  std::ostringstream out;
  out << e;
  EXPECT_EQ(out.str(), brief);
}

TEST(ResultJson, RegisterAndCorrect) {
  const ResultCell cell;
  const RegisterResult r = register_fiducials(cell.fiducials);
  const nlohmann::json j = register_json(r);
  EXPECT_EQ(j["n_fiducials"], 27);
  EXPECT_DOUBLE_EQ(j["fre_mm"].get<double>(), 1e3 * r.registration.fre_m);
  EXPECT_DOUBLE_EQ(j["translation_mm"][1].get<double>(),
                   1e3 * r.model.T_robot_sensor.translation_m.y());
  EXPECT_EQ(j["rejected"].size(), 0u);
  EXPECT_EQ(fmt::format("{}", r).rfind("27 fiducials, FRE ", 0), 0u) << fmt::format("{}", r);

  const CorrectResult c = correct(r.model, cell.targets);
  const nlohmann::json k = correct_json(c);
  EXPECT_EQ(k["points"], 3);
  EXPECT_EQ(k["n_flagged"], c.correction.n_flagged);
  EXPECT_EQ(fmt::format("{}", c), brief_report(c));
}

// A cross-validation note names an option the library's way; the command line and Python put
// their own words in (option_flags.cpp, errors.cpp).
TEST(ResultJson, CrossValidationNotesNameOptions) {
  CrossValidation cv;
  cv.folds = 5;
  CrossValidationRow row;
  row.method = InterpolationMethod::kJoint;
  row.applicable = false;
  row.note = "no robot given (`robot`)";
  cv.rows.push_back(row);
  const nlohmann::json j = cross_validation_json(cv);
  EXPECT_EQ(j["rows"][0]["note"], "no robot given (`robot`)");
  EXPECT_FALSE(j["rows"][0].contains("rms_mm"));
}

}  // namespace
}  // namespace vrreg::io
