// SPDX-License-Identifier: Apache-2.0
// Table 1's runner on a hand-made cell whose figures are known in closed form: fiducials on a
// 3 x 3 x 3 grid (h = 50 mm) measured with a scale error delta (X = Y + delta (Y - c)), which the
// registration cannot absorb and RRBC interpolates exactly; eight targets at the centres of the
// eight 50 mm sub-cubes, seven read with the same scale error, one with the opposite error.
#include "vrreg/experiments/table1.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg::experiments {
namespace {

constexpr double kH = 0.050;        // grid spacing and octuplet edge [m]
constexpr double kDelta = 1e-3;     // scale error of the sensor readings
constexpr double kSigma = 0.05e-3;  // per-axis noise of the repeat readings [m]
const Eigen::Vector3d kCellCentre(0.4, -0.1, 0.3);

Location location(const std::string& name, Role role, const Eigen::Vector3d& robot,
                  const Eigen::Vector3d& sensor) {
  Location l;
  l.point = name;
  l.role = role;
  l.robot_m = robot;
  l.sensor_m = sensor;
  l.n_readings = 3;  // per-axis sample variance = sq_dev / (3 - 1) = sigma^2
  l.sensor_sq_dev_m2 = Eigen::Vector3d::Constant(2.0 * kSigma * kSigma);
  return l;
}

MeasurementSet hand_cell() {
  MeasurementSet set;
  set.source = "hand.csv";
  set.has_repeat = true;
  for (int i = -1; i <= 1; ++i) {
    for (int j = -1; j <= 1; ++j) {
      for (int k = -1; k <= 1; ++k) {
        const Eigen::Vector3d y = kCellCentre + kH * Eigen::Vector3d(i, j, k);
        set.locations.push_back(location("F" + std::to_string(set.locations.size()),
                                         Role::kFiducial, y, y + kDelta * (y - kCellCentre)));
      }
    }
  }
  for (int t = 0; t < 8; ++t) {
    const Eigen::Vector3d o =
        0.5 * kH * Eigen::Vector3d(t & 1 ? 1 : -1, t & 2 ? 1 : -1, t & 4 ? 1 : -1);
    const Eigen::Vector3d y = kCellCentre + o;
    const Eigen::Vector3d error =
        t < 7 ? Eigen::Vector3d(kDelta * o) : Eigen::Vector3d(-kDelta * o);
    set.locations.push_back(location("T" + std::to_string(t), Role::kTarget, y, y + error));
  }
  return set;
}

// Sample sd of the 351 pairwise distances of the 3 x 3 x 3 grid, by brute force.
double grid_distance_sd() {
  std::vector<Eigen::Vector3d> p;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) p.push_back(kH * Eigen::Vector3d(i, j, k));
  std::vector<double> d;
  for (std::size_t a = 0; a < p.size(); ++a)
    for (std::size_t b = a + 1; b < p.size(); ++b) d.push_back((p[a] - p[b]).norm());
  double mean = 0.0;
  for (double v : d) mean += v / static_cast<double>(d.size());
  double ss = 0.0;
  for (double v : d) ss += (v - mean) * (v - mean);
  return std::sqrt(ss / static_cast<double>(d.size() - 1));
}

TEST(Table1, HandMadeCellGivesTheClosedFormFigures) {
  Table1Options options;
  options.cube_edge_m = kH;
  options.sigma_rep_m = 0.1e-3;
  options.l_histogram_bin_m = 0.001e-3;
  const Table1Entry e = run_table1_entry(hand_cell(), "hand", options);
  const RrbcRunFigures& f = e.figures;
  EXPECT_EQ(e.dataset, "hand");
  EXPECT_DOUBLE_EQ(e.d_m, 0.5 * std::sqrt(3.0) * kH);  // 43.3 mm
  EXPECT_EQ(f.n_fiducials, 27);
  EXPECT_EQ(f.n_targets, 8);
  EXPECT_NEAR(f.sigma_opt_m, kSigma, 1e-15);
  EXPECT_NEAR(f.sigma_noise_m, std::hypot(0.05e-3, 0.1e-3), 1e-15);
  // L_ij = delta |Y_i - Y_j| exactly, so sigma_L = delta sd(|Y_i - Y_j|).
  EXPECT_NEAR(f.sigma_l_m, kDelta * grid_distance_sd(), 1e-12);
  EXPECT_NEAR(f.rho, f.sigma_l_m / f.sigma_noise_m, 1e-12);
  // Every target is read delta |o| = delta h sqrt(3) / 2 off; RRBC removes the scale error,
  // leaving 0 for seven targets and 2 delta |o| for the eighth, which got worse.
  const double off = kDelta * kH * std::sqrt(3.0) / 2.0;
  EXPECT_NEAR(f.unc_rms_t_m, off, 1e-12);
  EXPECT_NEAR(f.cor_rms_t_m, 2.0 * off / std::sqrt(8.0), 1e-12);
  EXPECT_NEAR(f.gamma, 1.0 - 1.0 / std::sqrt(2.0), 1e-9);
  EXPECT_EQ(f.n_bad, 1);
  EXPECT_EQ(f.n_flagged, 0);
  ASSERT_EQ(f.cor_tre_m.size(), 8);
  EXPECT_NEAR(f.cor_tre_m[0], 0.0, 1e-12);
  EXPECT_NEAR(f.cor_tre_m[7], 2.0 * off, 1e-12);
  ASSERT_TRUE(f.l_histogram.has_value());
  std::int64_t pairs = f.l_histogram->below + f.l_histogram->above;
  for (const std::int64_t c : f.l_histogram->counts) pairs += c;
  EXPECT_EQ(pairs, 27 * 26 / 2);
  EXPECT_EQ(f.l_histogram->below + f.l_histogram->above, 0);
}

TEST(Table1, RejectsBadOptions) {
  Table1Options options;
  options.cube_edge_m = 0.0;
  EXPECT_THROW(run_table1_entry(hand_cell(), "hand", options), InputError);
  options.cube_edge_m = kH;
  options.sigma_rep_m = -1.0;
  EXPECT_THROW(run_table1_entry(hand_cell(), "hand", options), InputError);
}

}  // namespace
}  // namespace vrreg::experiments
