// SPDX-License-Identifier: Apache-2.0
// Fiducials in a plane (or on a line) register (three points off a line suffice) but hold no
// tetrahedron: `linear` and `scattered` fit, and answer every point uncorrected with the status
// "flat layout" and a description that says why, instead of refusing the whole run; saved and
// restored, the same. Extrapolation does not apply: there is nothing to extrapolate from.
#include <gtest/gtest.h>

#include <string>

#include "vrreg/correction/corrector.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

// Nine fiducials on a 3 x 3 grid at 25 mm in the plane z = 0.3 m (or, `line`, nine on a line),
// read by a sensor shifted 1 m along x with 20 um of noise; three targets, one off the plane.
struct FlatCell {
  CorrectorData data;
  Points3 targets_sensor_m;
  explicit FlatCell(bool line) {
    Random rng(4);
    Points3 robot(3, 9);
    for (int j = 0; j < 9; ++j) {
      robot.col(j) = line ? Eigen::Vector3d(0.4 + 0.025 * j, -0.1, 0.3)
                          : Eigen::Vector3d(0.4 + 0.025 * (j % 3), -0.1 + 0.025 * (j / 3), 0.3);
    }
    SimilarityTransform T;
    T.translation_m = Eigen::Vector3d(1.0, 0.0, 0.0);
    Points3 sensor(3, 9);
    for (int j = 0; j < 9; ++j) sensor.col(j) = robot.col(j) - T.translation_m + rng.normal3(2e-5);
    data = CorrectorData::of(T, sensor, robot, fiducial_corrections(T, sensor, robot));
    targets_sensor_m.resize(3, 3);
    targets_sensor_m << -0.5875, -0.57, -0.6,  //
        -0.0875, -0.07, -0.1,                  //
        0.3, 0.31, 0.35;
  }
};

TEST(FlatLayout, LinearAndScatteredAnswerEveryPointUncorrectedWithTheReason) {
  for (const bool line : {false, true}) {
    const FlatCell cell(line);
    for (const InterpolationMethod method :
         {InterpolationMethod::kLinear, InterpolationMethod::kScattered}) {
      CorrectorOptions options;
      options.interpolation.method = method;
      const Corrector corrector = Corrector::fit(cell.data, options);
      EXPECT_EQ(corrector.method(), InterpolationMethod::kScattered);
      EXPECT_NE(corrector.describe().find("lie in a plane or on a line"), std::string::npos)
          << corrector.describe();
      for (const bool extrapolate : {false, true}) {
        CorrectionQuery query(cell.targets_sensor_m);
        query.extrapolate = extrapolate;
        const TargetCorrection c = corrector.correct(query);
        EXPECT_EQ(c.n_flagged, 3);
        for (std::size_t t = 0; t < 3; ++t) {
          EXPECT_EQ(c.stencils[t].status, StencilStatus::kFlatLayout) << t;
          EXPECT_EQ(c.corrected_robot_m.col(static_cast<Eigen::Index>(t)),
                    c.uncorrected_robot_m.col(static_cast<Eigen::Index>(t)));
        }
      }
      const Corrector restored = Corrector::restore(corrector.save(), cell.data);
      EXPECT_EQ(restored.describe(), corrector.describe());
      EXPECT_EQ(restored.correct(CorrectionQuery(cell.targets_sensor_m)).stencils[0].status,
                StencilStatus::kFlatLayout);
    }
  }
  EXPECT_STREQ(to_string(StencilStatus::kFlatLayout), "flat layout");
}

}  // namespace
}  // namespace vrreg
