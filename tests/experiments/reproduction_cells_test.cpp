// SPDX-License-Identifier: Apache-2.0
// The reproduction's cells: named by their JSON pointer, mean +- sd over seeds, key cells that
// must agree between seeds, and the JSON shapes of one seed (numbers) and of several ({mean, sd}).
#include "vrreg/experiments/reproduction_cells.hpp"

#include "vrreg/core/check.hpp"
#include "vrreg/experiments/reproduction_json.hpp"
#include "vrreg_test.hpp"

namespace vrreg::experiments {
namespace {

Reproduction small(double a1_cor_mm) {
  Reproduction r;
  r.seed = 3;
  RrbcRunFigures f;
  f.unc_rms_t_m = 0.6e-3;
  f.cor_rms_t_m = a1_cor_mm * 1e-3;
  f.gamma = 1.0 - a1_cor_mm / 0.6;
  f.n_bad = 3;
  f.n_targets = 120;
  r.a1 = Table1Entry{"A1", 0.050, 0.5 * std::sqrt(3.0) * 0.050, f};
  Table2 t;
  t.configs = {2};
  t.strategy2.n_points = 10;
  t.strategy2.n_locations = 20;
  t.strategy2.n_switched = 4;
  t.strategy2.n_switched_points = 3;
  for (int s = 1; s <= 3; ++s) t.entries.push_back({2, s, f, {}, {}});
  r.table2 = t;
  return r;
}

double value_of(const std::vector<Cell>& cells, const std::string& pointer) {
  for (const Cell& c : cells) {
    if (c.pointer == pointer) return c.value;
  }
  throw std::logic_error("no cell " + pointer);
}

TEST(ReproductionCells, NamedInMillimetresAndPercent) {
  const std::vector<Cell> cells = reproduction_cells(small(0.24));
  EXPECT_NEAR(value_of(cells, "/table1/A1/d_mm"), 43.30127, 1e-5);
  EXPECT_NEAR(value_of(cells, "/table1/A1/cor_rms_t_mm"), 0.24, 1e-12);
  EXPECT_NEAR(value_of(cells, "/table1/A1/gamma_percent"), 60.0, 1e-9);
  EXPECT_DOUBLE_EQ(value_of(cells, "/kuka/switched_points_fraction"), 0.3);
  EXPECT_DOUBLE_EQ(value_of(cells, "/kuka/switched_locations_fraction"), 0.2);
  EXPECT_DOUBLE_EQ(value_of(cells, "/table2/2/strategy"), 3.0);
  EXPECT_TRUE(std::isnan(value_of(cells, "/table2/2/sigma_l_mm")));  // Strategy 3: not defined
  EXPECT_TRUE(std::isnan(value_of(cells, "/kuka/cor_rms_t_spread_percent/0")));  // one config
}

TEST(ReproductionCells, MeanAndSdOverSeeds) {
  const CellTable t =
      summarize_cells({reproduction_cells(small(0.20)), reproduction_cells(small(0.24)),
                       reproduction_cells(small(0.28))});
  EXPECT_EQ(t.n_seeds, 3);
  const CellSummary* c = t.find("/table1/A1/cor_rms_t_mm");
  ASSERT_NE(c, nullptr);
  EXPECT_NEAR(c->mean, 0.24, 1e-12);
  EXPECT_NEAR(c->sd, 0.04, 1e-12);
  EXPECT_NEAR(c->median, 0.24, 1e-12);
  EXPECT_EQ(c->n, 3);
  // The median of an even count is the mean of the middle two, not the mean of all.
  const CellTable even = summarize_cells(
      {reproduction_cells(small(0.20)), reproduction_cells(small(0.22)),
       reproduction_cells(small(0.30)), reproduction_cells(small(0.40))});
  EXPECT_NEAR(even.find("/table1/A1/cor_rms_t_mm")->median, 0.26, 1e-12);
  EXPECT_EQ(t.find("/nothing"), nullptr);
  std::vector<Cell> other = reproduction_cells(small(0.2));
  other.front().value = 25.0;  // d_mm is a key: it must be the same on every seed
  EXPECT_THROW(summarize_cells({reproduction_cells(small(0.2)), other}), InputError);
  other = reproduction_cells(small(0.2));
  other.pop_back();
  EXPECT_THROW(summarize_cells({reproduction_cells(small(0.2)), other}), InputError);
}

TEST(ReproductionJson, NumbersForOneSeedMeanAndSdForSeveral) {
  const nlohmann::json one = reproduction_json({small(0.24)});
  EXPECT_EQ(one["format"], "vrreg-reproduce");
  EXPECT_EQ(one["seed"], 3);
  EXPECT_EQ(one["seeds"], nlohmann::json::array({3}));
  EXPECT_NEAR(one["table1"]["A1"]["cor_rms_t_mm"].get<double>(), 0.24, 1e-12);
  EXPECT_TRUE(one["table1"]["A1"]["n_bad"].is_number_integer());
  EXPECT_TRUE(one["table2"].is_array());
  EXPECT_EQ(one["table2"].size(), 3u);
  EXPECT_TRUE(one["table2"][0]["config"].is_number_integer());
  EXPECT_TRUE(one["table2"][2]["sigma_l_mm"].is_null());
  EXPECT_EQ(one["findings"].size(), 6u);
  EXPECT_TRUE(one["findings"][0].contains("met"));
  EXPECT_DOUBLE_EQ(one["switched_fraction"].get<double>(), 0.3);

  Reproduction second = small(0.28);
  second.seed = 4;
  const nlohmann::json two = reproduction_json({small(0.20), second});
  EXPECT_EQ(two["seeds"], nlohmann::json::array({3, 4}));
  EXPECT_NEAR(two["table1"]["A1"]["cor_rms_t_mm"]["mean"].get<double>(), 0.24, 1e-12);
  EXPECT_NEAR(two["table1"]["A1"]["cor_rms_t_mm"]["sd"].get<double>(), std::sqrt(0.0032), 1e-12);
  EXPECT_EQ(two["table2"][1]["strategy"], 2);   // keys stay plain integers
  EXPECT_EQ(two["findings"][0]["n_seeds"], 0);  // no A2: gamma(A2) > gamma(A1) not evaluated
  EXPECT_EQ(two["findings"][4]["n_seeds"], 2);
}

}  // namespace
}  // namespace vrreg::experiments
