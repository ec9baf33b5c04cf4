// SPDX-License-Identifier: Apache-2.0
// Dataset B's sweep (Figures 7, 8, 11) on a hand-made cell: one target at c, fiducials at the
// corners of cubes of 40 and 20 mm around it, read with a quadratic error q |Y - c|^2 along z.
// The registration is then the identity shifted by -q m (m = mean |Y - c|^2 = 0.00075 m^2), so
// unc TRE = q m and cor TRE(a) = 3/4 q a^2: 0.12 mm (worse) at a = 40 mm, 0.03 mm at 20 mm.
#include "vrreg/experiments/distance_sweep.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg::experiments {
namespace {

constexpr double kQ = 0.1;  // [1/m]
const Eigen::Vector3d kSweepCentre(0.5, 0.2, 0.3);

MeasurementSet quadratic_cell() {
  MeasurementSet set;
  set.source = "b.csv";
  Location target;
  target.point = "T";
  target.role = Role::kTarget;
  target.robot_m = kSweepCentre;
  target.sensor_m = kSweepCentre;
  target.source_line = 1;
  set.locations.push_back(target);
  for (const double a : {0.040, 0.020}) {
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d o =
          0.5 * a * Eigen::Vector3d(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
      Location f;
      f.point = "F" + std::to_string(set.locations.size());
      f.robot_m = kSweepCentre + o;
      f.sensor_m = f.robot_m + kQ * o.squaredNorm() * Eigen::Vector3d::UnitZ();
      f.source_line = set.locations.size() + 1;
      set.locations.push_back(f);
    }
  }
  return set;
}

TEST(DistanceSweep, QuadraticErrorGivesTheClosedFormCurve) {
  DistanceSweepOptions options;
  options.cube_edges_m = {0.040, 0.020};
  const DistanceSweep s = run_distance_sweep(quadratic_cell(), options);
  EXPECT_EQ(s.n_fiducials, 16);
  EXPECT_EQ(s.target_points, (std::vector<std::string>{"T"}));
  const double m = (3.0 * 0.02 * 0.02 + 3.0 * 0.01 * 0.01) / 2.0;
  EXPECT_NEAR(s.unc_rms_t_m, kQ * m, 1e-12);  // 0.075 mm
  ASSERT_EQ(s.steps.size(), 2u);
  EXPECT_NEAR(s.steps[0].d_m, 0.5 * std::sqrt(3.0) * 0.040, 1e-15);
  EXPECT_NEAR(s.steps[0].cor_rms_t_m, 0.75 * kQ * 0.040 * 0.040, 1e-12);  // 0.12 mm
  EXPECT_EQ(s.steps[0].n_bad, 1);
  EXPECT_EQ(s.steps[0].bad_targets, (std::vector<int>{0}));
  EXPECT_NEAR(s.steps[0].gamma, 1.0 - 0.12 / 0.075, 1e-9);
  EXPECT_NEAR(s.steps[1].cor_rms_t_m, 0.75 * kQ * 0.020 * 0.020, 1e-12);  // 0.03 mm
  EXPECT_EQ(s.steps[1].n_bad, 0);
  EXPECT_NEAR(s.steps[1].gamma, 0.6, 1e-9);
  EXPECT_EQ(&s.at_d_max(), &s.steps[0]);
  EXPECT_EQ(&s.at_d_min(), &s.steps[1]);
  // Figure 11: Delta TRE = 0.03 - 0.075 mm in the bin [-0.05, -0.04) mm of 0.01 mm bins to 0.
  ASSERT_EQ(s.delta_tre_at_d_min_m.size(), 1);
  EXPECT_NEAR(s.delta_tre_at_d_min_m[0], -0.045e-3, 1e-12);
  EXPECT_NEAR(s.delta_tre_histogram.lo_m, -0.05e-3, 1e-15);
  EXPECT_EQ(s.delta_tre_histogram.counts, (std::vector<std::int64_t>{1, 0, 0, 0, 0}));
}

TEST(DistanceSweep, MissingCubeIsFlaggedAndLeftUncorrected) {
  DistanceSweepOptions options;
  options.cube_edges_m = {0.030};
  const DistanceSweep s = run_distance_sweep(quadratic_cell(), options);
  EXPECT_EQ(s.steps[0].n_flagged, 1);
  EXPECT_NEAR(s.steps[0].cor_rms_t_m, s.unc_rms_t_m, 1e-15);
}

TEST(DistanceSweep, DatasetBEdgesAndBadInput) {
  const std::vector<double> edges = dataset_b_cube_edges_m();
  ASSERT_EQ(edges.size(), 10u);
  EXPECT_DOUBLE_EQ(edges.front(), 0.050);
  EXPECT_DOUBLE_EQ(edges.back(), 0.005);
  DistanceSweepOptions options;
  options.cube_edges_m = {};
  EXPECT_THROW(run_distance_sweep(quadratic_cell(), options), InputError);
  MeasurementSet no_targets = quadratic_cell();
  no_targets.locations.erase(no_targets.locations.begin());
  EXPECT_THROW(run_distance_sweep(no_targets, {}), InputError);
}

}  // namespace
}  // namespace vrreg::experiments
