// SPDX-License-Identifier: Apache-2.0
// Multi-directional accuracy against a small example computed by hand: points joined by name or
// by nominal position within 1 um, single-direction points and unknown directions left out.
#include "vrreg/metrics/multidirectional.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

TEST(MultidirectionalAccuracy, MatchesAHandComputedExample) {
  struct Row {
    const char* name;
    Eigen::Vector3d nominal_m;
    std::vector<double> sign;
    Eigen::Vector3d error_mm;
    bool included;
  };
  const std::vector<Row> rows = {
      {"a", {0, 0, 0}, {1, 1}, {1, 0, 0}, true},
      {"a", {0, 0, 0}, {1, 1}, {3, 0, 0}, true},
      {"a2", {0, 0, 5e-7}, {-1, -1}, {0, 2, 0}, true},  // point a by position (0.5 um away)
      {"e", {0, 0, 2e-6}, {-1, -1}, {9, 9, 9}, true},   // 2 um away: a point of its own
      {"b", {0.1, 0, 0}, {1, 1}, {0, 0, 1}, true},
      {"b", {0.1, 0, 0}, {-1, -1}, {0, 0, -1}, true},
      {"b", {0.1, 0, 0}, {1, -1}, {0, 0, 0}, true},
      {"b", {0.1, 0, 0}, {-1, -1}, {100, 0, 0}, false},  // not included (e.g. not corrected)
      {"c", {0.2, 0, 0}, {1, 1}, {5, 5, 5}, true},       // one direction only
      {"c", {0.2, 0, 0}, {}, {7, 7, 7}, true},           // direction unknown
  };
  const auto n = static_cast<Eigen::Index>(rows.size());
  Points3 nominal(3, n), unc(3, n), cor(3, n);
  std::vector<std::vector<double>> signs;
  std::vector<std::string> names;
  std::vector<bool> included;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Row& r = rows[static_cast<std::size_t>(i)];
    nominal.col(i) = r.nominal_m;
    unc.col(i) = r.nominal_m + 1e-3 * r.error_mm;
    cor.col(i) = r.nominal_m + 0.5e-3 * r.error_mm;
    signs.push_back(r.sign);
    names.emplace_back(r.name);
    included.push_back(r.included);
  }
  const MultidirectionalAccuracy m =
      multidirectional_accuracy(nominal, unc, cor, signs, names, {}, included);
  ASSERT_EQ(m.n_points, 2);
  EXPECT_EQ(m.point_names, (std::vector<std::string>{"a", "b"}));
  // a: means (2, 0, 0) and (0, 2, 0) mm -> sqrt(8); b: (0, 0, 1), (0, 0, -1), 0 -> 2.
  ASSERT_EQ(m.unc_spread_m.size(), 2);
  EXPECT_NEAR(m.unc_spread_m(0), 1e-3 * std::sqrt(8.0), 1e-15);
  EXPECT_NEAR(m.unc_spread_m(1), 2e-3, 1e-15);
  EXPECT_NEAR(m.unc_max_spread_m, 1e-3 * std::sqrt(8.0), 1e-15);
  EXPECT_NEAR(m.unc_mean_spread_m, 0.5e-3 * (std::sqrt(8.0) + 2.0), 1e-15);
  EXPECT_NEAR(m.cor_max_spread_m, 0.5e-3 * std::sqrt(8.0), 1e-15);
  EXPECT_NEAR(m.cor_mean_spread_m, 0.25e-3 * (std::sqrt(8.0) + 2.0), 1e-15);
  ASSERT_EQ(m.directions.size(), 3u);
  EXPECT_EQ(approach_text(m.directions[0].approach_sign), "++");
  EXPECT_EQ(approach_text(m.directions[1].approach_sign), "--");
  EXPECT_EQ(approach_text(m.directions[2].approach_sign), "+-");
  EXPECT_EQ(m.directions[0].n_targets, 3);  // a, a, b
  EXPECT_EQ(m.directions[1].n_targets, 2);  // a2, b
  EXPECT_EQ(m.directions[2].n_targets, 1);
  EXPECT_NEAR(m.directions[0].unc_rms_t_m, 1e-3 * std::sqrt(11.0 / 3.0), 1e-15);
  EXPECT_NEAR(m.directions[1].unc_rms_t_m, 1e-3 * std::sqrt(2.5), 1e-15);
  EXPECT_NEAR(m.directions[1].cor_rms_t_m, 0.5e-3 * std::sqrt(2.5), 1e-15);
  EXPECT_EQ(m.directions[2].unc_rms_t_m, 0.0);
  // Without names the points come from positions only: a and a2 still join, b too.
  const MultidirectionalAccuracy by_position =
      multidirectional_accuracy(nominal, unc, cor, signs, {}, {}, included);
  EXPECT_EQ(by_position.n_points, 2);
  EXPECT_NEAR(by_position.unc_max_spread_m, m.unc_max_spread_m, 1e-15);
  EXPECT_EQ(by_position.point_names[0], "#1");
  EXPECT_EQ(approach_text({0.0, -1.0, 1.0}), "0-+");
  // One point in two arm configurations is two points (other joints, not other directions).
  std::vector<std::optional<int>> configs(rows.size(), 1);
  configs[2] = 2;  // a2: config 2, by position it no longer joins a
  configs[5] = 2;  // b from -, config 2
  const MultidirectionalAccuracy by_config =
      multidirectional_accuracy(nominal, unc, cor, signs, names, configs, included);
  EXPECT_EQ(by_config.n_points, 1);  // b (config 1) from ++ and +-: spread 1 mm
  EXPECT_NEAR(by_config.unc_max_spread_m, 1e-3, 1e-15);
}

TEST(MultidirectionalAccuracy, NothingWhenNoPointHasTwoDirections) {
  Points3 p = Points3::Random(3, 4);
  const MultidirectionalAccuracy m =
      multidirectional_accuracy(p, p, p, {{1.0}, {1.0}, {-1.0}, {}}, {"a", "a", "b", "b"});
  EXPECT_EQ(m.n_points, 0);
  EXPECT_TRUE(m.directions.empty());
  EXPECT_EQ(m.unc_max_spread_m, 0.0);
  EXPECT_THROW((void)multidirectional_accuracy(p, p, p, {{1.0}}, {}), InputError);
}

}  // namespace
}  // namespace vrreg
