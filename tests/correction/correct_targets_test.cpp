// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/correct_targets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "correction_fixtures.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/correction/grid.hpp"
#include "vrreg/correction/scattered.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

using testing::a1_layout;
using testing::grid_points;
using testing::random_points;
using testing::random_transform;

/// A smooth + wavy robot error [m] at a nominal robot position: what the sensor sees is off.
Eigen::Vector3d robot_error_m(const Eigen::Vector3d& p) {
  return Eigen::Vector3d(4e-4 * std::sin(18.0 * p.y()) + 2e-3 * p.x() * p.z(),
                         3e-4 * std::cos(21.0 * p.z()) - 1e-3 * p.x(),
                         2e-4 * std::sin(25.0 * p.x() + 9.0 * p.y()) + 5e-4 * p.y());
}

/// A correction field whose fiducials at fiducials_robot_m are measured with robot_error_m
/// through T.
CorrectionField make_model(const Points3& fiducials_robot_m,
                           const SimilarityTransform& T_robot_sensor) {
  CorrectionField model;
  model.T_robot_sensor = T_robot_sensor;
  model.fiducials_robot_m = fiducials_robot_m;
  Points3 sensor(3, fiducials_robot_m.cols());
  const SimilarityTransform T_sensor_robot = T_robot_sensor.inverse();
  for (Eigen::Index j = 0; j < fiducials_robot_m.cols(); ++j) {
    const Eigen::Vector3d robot_m = fiducials_robot_m.col(j);
    sensor.col(j) = T_sensor_robot.apply(Eigen::Vector3d(robot_m + robot_error_m(robot_m)));
  }
  model.corrections_sensor_m = fiducial_corrections(T_robot_sensor, sensor, fiducials_robot_m);
  return model;
}

Points3 measure(const Points3& targets_robot_m, const SimilarityTransform& T_robot_sensor) {
  Points3 out(3, targets_robot_m.cols());
  const SimilarityTransform inv = T_robot_sensor.inverse();
  for (Eigen::Index i = 0; i < out.cols(); ++i) {
    out.col(i) =
        inv.apply(Eigen::Vector3d(targets_robot_m.col(i) + robot_error_m(targets_robot_m.col(i))));
  }
  return out;
}

double rms_m(const Points3& a, const Points3& b) {
  return std::sqrt((a - b).colwise().squaredNorm().mean());
}

InterpolationSettings with(InterpolationMethod method, double cube_edge_m = 0.0) {
  InterpolationSettings s;
  s.method = method;
  s.cube_edge_m = cube_edge_m;
  return s;
}

class CorrectTargets : public ::testing::Test {
 protected:
  Random rng{53};
  RigidTransform T = random_transform(rng, 1.5);
  testing::A1Layout a1 = a1_layout();
  CorrectionField model = make_model(a1.fiducials_robot_m, T);
  Points3 targets_sensor = measure(a1.targets_robot_m, T);
};

TEST_F(CorrectTargets, AutoPicksTheGridOnA1AndAllMethodsImprove) {
  const TargetCorrection grid =
      correct_targets(model, targets_sensor, Points3(3, 0), with(InterpolationMethod::kLinear));
  EXPECT_EQ(grid.method_used, InterpolationMethod::kGrid);
  EXPECT_EQ(grid.layout,
            "grid 6 x 7 x 5 nodes, 50 x 50 x 50 mm (every 2nd fiducial; 210 of 1167 fiducials)");
  const TargetCorrection octuplet = correct_targets(model, targets_sensor, a1.targets_robot_m,
                                                    with(InterpolationMethod::kOctuplet, 0.05));
  EXPECT_EQ(octuplet.method_used, InterpolationMethod::kOctuplet);
  // A1's targets sit at the centres of the 50 mm grid cells: the grid uses the octuplet's 8
  // fiducials, with weights near 1/8 (it weighs at the registered, not the nominal, position).
  for (std::size_t i = 0; i < grid.stencils.size(); ++i) {
    auto a = grid.stencils[i].fiducial;
    auto b = octuplet.stencils[i].fiducial;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b);
    for (const double w : grid.stencils[i].weight) EXPECT_NEAR(w, 0.125, 0.01);
  }
  const TargetCorrection scattered =
      correct_targets(model, targets_sensor, Points3(3, 0), with(InterpolationMethod::kScattered));
  EXPECT_EQ(scattered.method_used, InterpolationMethod::kScattered);
  const double unc = rms_m(grid.uncorrected_robot_m, a1.targets_robot_m);
  for (const TargetCorrection* c : {&grid, &octuplet, &scattered}) {
    EXPECT_EQ(c->n_flagged, 0);
    EXPECT_LT(rms_m(c->corrected_robot_m, a1.targets_robot_m), 0.5 * unc) << c->layout;
    for (Eigen::Index i = 0; i < targets_sensor.cols(); ++i) {
      // Eq. 7, 8 and the mapping, target by target.
      EXPECT_EIGEN_NEAR(c->corrections_sensor_m.col(i),
                        interpolate_correction(c->stencils[static_cast<std::size_t>(i)],
                                               model.corrections_sensor_m),
                        1e-18);
      EXPECT_EIGEN_NEAR(c->corrected_sensor_m.col(i),
                        targets_sensor.col(i) + c->corrections_sensor_m.col(i), 1e-15);
      EXPECT_EIGEN_NEAR(c->corrected_robot_m.col(i),
                        T.apply(Eigen::Vector3d(c->corrected_sensor_m.col(i))), 1e-15);
      EXPECT_EIGEN_NEAR(c->uncorrected_robot_m.col(i),
                        T.apply(Eigen::Vector3d(targets_sensor.col(i))), 1e-15);
    }
  }
}

TEST_F(CorrectTargets, ExactAtFiducials) {
  // Targets whose registered positions are fiducials get exactly those fiducials' corrections,
  // and a fiducial's corrected position maps onto its robot position (Eq. 5, 6).
  const Points3 sensor = T.inverse().apply_all(a1.fiducials_robot_m);
  for (const auto method : {InterpolationMethod::kScattered, InterpolationMethod::kLinear}) {
    const TargetCorrection c = correct_targets(model, sensor, Points3(3, 0), with(method));
    ASSERT_EQ(c.n_flagged, 0);
    for (Eigen::Index j = 0; j < sensor.cols(); ++j) {
      if (c.method_used == InterpolationMethod::kGrid) {  // only the sub-lattice's nodes are exact
        const auto& s = c.stencils[static_cast<std::size_t>(j)];
        if (std::find(s.fiducial.begin(), s.fiducial.end(), j) == s.fiducial.end()) continue;
      }
      EXPECT_EIGEN_NEAR(c.corrections_sensor_m.col(j), model.corrections_sensor_m.col(j), 1e-15);
    }
  }
  Points3 measured(3, model.fiducials_robot_m.cols());
  for (Eigen::Index j = 0; j < measured.cols(); ++j) {
    const Eigen::Vector3d robot_m = a1.fiducials_robot_m.col(j);
    measured.col(j) = T.inverse().apply(Eigen::Vector3d(robot_m + robot_error_m(robot_m)));
  }
  EXPECT_EIGEN_NEAR(T.apply_all(measured + model.corrections_sensor_m), a1.fiducials_robot_m,
                    1e-12);
}

TEST_F(CorrectTargets, CorrectedErrorFallsWithGridSpacing) {
  Random points_rng(59);
  const Points3 targets_robot =
      random_points(points_rng, 500, 0.095, Eigen::Vector3d(0.1, 0.1, 0.1));
  const Points3 sensor = measure(targets_robot, T);
  double previous = std::numeric_limits<double>::infinity();
  for (const int n : {3, 5, 9, 17}) {
    const double h = 0.2 / (n - 1);
    const CorrectionField m = make_model(grid_points(n, n, n, Eigen::Vector3d::Constant(h)), T);
    const TargetCorrection c =
        correct_targets(m, sensor, Points3(3, 0), with(InterpolationMethod::kGrid));
    ASSERT_EQ(c.n_flagged, 0);
    const double cor = rms_m(c.corrected_robot_m, targets_robot);
    EXPECT_LT(cor, 0.6 * previous) << "spacing " << h;
    previous = cor;
  }
  EXPECT_LT(previous, 0.05 * rms_m(T.apply_all(sensor), targets_robot));
}

TEST_F(CorrectTargets, FlagsTargetsOutsideAndKeepsTheirUncorrectedMapping) {
  Points3 sensor = targets_sensor;
  sensor.col(0) = T.inverse().apply(Eigen::Vector3d(2.0, 2.0, 2.0));
  sensor.col(1) = T.inverse().apply(Eigen::Vector3d(0.2, -0.1, 0.1));
  for (const auto method : {InterpolationMethod::kGrid, InterpolationMethod::kScattered}) {
    const TargetCorrection c = correct_targets(model, sensor, Points3(3, 0), with(method));
    EXPECT_EQ(c.n_flagged, 2);
    for (Eigen::Index i : {0, 1}) {
      EXPECT_NE(c.stencils[static_cast<std::size_t>(i)].status, StencilStatus::kOk);
      EXPECT_EIGEN_NEAR(c.corrections_sensor_m.col(i), Eigen::Vector3d::Zero(), 0.0);
      EXPECT_EIGEN_NEAR(c.corrected_robot_m.col(i), c.uncorrected_robot_m.col(i), 0.0);
    }
  }
  Points3 nominal = a1.targets_robot_m;
  nominal.col(5) += Eigen::Vector3d(0.003, 0, 0);  // no cube corners there
  const TargetCorrection c =
      correct_targets(model, targets_sensor, nominal, with(InterpolationMethod::kOctuplet, 0.05));
  EXPECT_EQ(c.n_flagged, 1);
  EXPECT_EQ(c.stencils[5].status, StencilStatus::kMissingCorner);
}

TEST_F(CorrectTargets, AutoFallsBackToScatteredAndGridRequestThrows) {
  Random points_rng(61);
  const CorrectionField random_model = make_model(random_points(points_rng, 200, 0.1), T);
  const Points3 sensor = measure(random_points(points_rng, 20, 0.02), T);
  const TargetCorrection c =
      correct_targets(random_model, sensor, Points3(3, 0), with(InterpolationMethod::kLinear));
  EXPECT_EQ(c.method_used, InterpolationMethod::kScattered);
  EXPECT_NE(c.layout.find("scattered"), std::string::npos);
  try {
    (void)correct_targets(random_model, sensor, Points3(3, 0), with(InterpolationMethod::kGrid));
    ADD_FAILURE() << "grid on scattered fiducials accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("complete regular grid"), std::string::npos) << e.what();
  }
}

TEST_F(CorrectTargets, RejectsUnusableInput) {
  const Points3 none(3, 0);
  EXPECT_THROW((void)correct_targets(model, targets_sensor, none,
                                     with(InterpolationMethod::kOctuplet, 0.05)),
               InputError);
  EXPECT_THROW((void)correct_targets(model, targets_sensor, a1.targets_robot_m,
                                     with(InterpolationMethod::kOctuplet)),
               InputError);
  EXPECT_THROW((void)correct_targets(model, targets_sensor, a1.targets_robot_m.leftCols(3),
                                     with(InterpolationMethod::kGrid)),
               InputError);
  Points3 nan = targets_sensor;
  nan(0, 7) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)correct_targets(model, nan, none, with(InterpolationMethod::kGrid)),
               InputError);
  CorrectionField short_model = model;
  short_model.corrections_sensor_m = model.corrections_sensor_m.leftCols(10);
  EXPECT_THROW(
      (void)correct_targets(short_model, targets_sensor, none, with(InterpolationMethod::kLinear)),
      InputError);
  CorrectionField empty;
  EXPECT_THROW((void)correct_targets(empty, targets_sensor, none, with(InterpolationMethod::kLinear)),
               InputError);
}

// Fiducials in a plane are answered, not refused: every target uncorrected, "flat layout".
TEST_F(CorrectTargets, AFlatLayoutLeavesEveryTargetUncorrected) {
  const Points3 none(3, 0);
  const CorrectionField flat = make_model(grid_points(5, 5, 1, Eigen::Vector3d::Constant(0.02)), T);
  const TargetCorrection c =
      correct_targets(flat, targets_sensor, none, with(InterpolationMethod::kLinear));
  EXPECT_EQ(c.n_flagged, targets_sensor.cols());
  for (const Stencil& s : c.stencils) EXPECT_EQ(s.status, StencilStatus::kFlatLayout);
  EXPECT_EQ(c.corrected_robot_m, c.uncorrected_robot_m);
}

TEST_F(CorrectTargets, ScaleIsApplied) {
  const SimilarityTransform scaled(T, 1.002);
  const CorrectionField m = make_model(a1.fiducials_robot_m, scaled);
  const Points3 sensor = measure(a1.targets_robot_m, scaled);
  const TargetCorrection c =
      correct_targets(m, sensor, Points3(3, 0), with(InterpolationMethod::kGrid));
  for (Eigen::Index i = 0; i < sensor.cols(); ++i) {
    EXPECT_EIGEN_NEAR(c.uncorrected_robot_m.col(i), scaled.apply(Eigen::Vector3d(sensor.col(i))),
                      1e-15);
  }
  EXPECT_LT(rms_m(c.corrected_robot_m, a1.targets_robot_m),
            0.5 * rms_m(c.uncorrected_robot_m, a1.targets_robot_m));
}

TEST_F(CorrectTargets, ParallelRunMatchesOneTargetAtATime) {
  Random points_rng(67);
  // Above 30 840 targets the stencils' 4 MiB are faulted in from both threads first.
  const int n = testing::sanitized() ? 32000 : 40000;
  const Points3 sensor =
      T.inverse().apply_all(random_points(points_rng, n, 0.12, Eigen::Vector3d(0.425, 0.05, 0.15)));
  for (const auto method : {InterpolationMethod::kGrid, InterpolationMethod::kScattered}) {
    const TargetCorrection all = correct_targets(model, sensor, Points3(3, 0), with(method));
    for (Eigen::Index i = 0; i < n; i += n / 7) {
      const TargetCorrection one =
          correct_targets(model, sensor.col(i), Points3(3, 0), with(method));
      EXPECT_EIGEN_NEAR(one.corrected_robot_m.col(0), all.corrected_robot_m.col(i), 0.0);
      EXPECT_EQ(one.stencils[0].status, all.stencils[static_cast<std::size_t>(i)].status);
    }
    const auto flagged =
        std::count_if(all.stencils.begin(), all.stencils.end(),
                      [](const Stencil& s) { return s.status != StencilStatus::kOk; });
    EXPECT_EQ(all.n_flagged, flagged);
  }
}

}  // namespace
}  // namespace vrreg
