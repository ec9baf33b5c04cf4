// SPDX-License-Identifier: Apache-2.0
// The whole reproduction on the simulated test beds (a few seconds, also under the sanitizers): the
// default seed meets every finding of the paper; the same seeds give the same bytes whatever the
// number of threads; dataset B's sweep agrees with the calibration's figures.
#include "vrreg/experiments/reproduction.hpp"

#include <tbb/global_control.h>

#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/experiments/findings.hpp"
#include "vrreg/experiments/reproduction_cells.hpp"
#include "vrreg/experiments/reproduction_csv.hpp"
#include "vrreg/experiments/reproduction_json.hpp"
#include "vrreg/experiments/testbed_calibration.hpp"
#include "vrreg_test.hpp"

namespace vrreg::experiments {
namespace {

TEST(Reproduction, DefaultSeedMeetsEveryFinding) {
  int steps = 0;
  const Reproduction r = run_reproduction({}, [&steps] { ++steps; });
  EXPECT_EQ(steps, reproduction_steps({}));
  ASSERT_TRUE(r.a1 && r.a2 && r.b && r.table2);
  EXPECT_EQ(r.a1->figures.n_targets, 120);
  EXPECT_EQ(r.a2->figures.n_fiducials, 7965);
  EXPECT_EQ(r.b->n_fiducials, 9600);
  for (const SweepStep& s : r.b->steps) EXPECT_EQ(s.n_flagged, 0) << s.cube_edge_m;
  EXPECT_EQ(r.table2->configs, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_NEAR(r.table2->strategy2.switched_points_fraction(), 0.164, 0.001);
  for (const Finding& f : evaluate_findings(r)) {
    EXPECT_TRUE(f.evaluated && f.met) << f.statement << ": " << f.detail;
  }
  // Dataset B as the test-bed calibration (docs/testbed-calibration.md) computed it.
  const Ur5SeedFigures c = calibrate_ur5(simulation::ur5_testbed(), 1, std::nullopt);
  ASSERT_EQ(c.b_cor_rms_t_m.size(), r.b->steps.size());
  for (std::size_t k = 0; k < r.b->steps.size(); ++k) {
    EXPECT_DOUBLE_EQ(c.b_cor_rms_t_m[k], r.b->steps[k].cor_rms_t_m);
    EXPECT_EQ(c.b_n_bad[k], r.b->steps[k].n_bad);
  }
  EXPECT_EQ(figure10_targets_csv(r).substr(0, 40), "n,point,robot_x_mm,robot_y_mm,robot_z_mm");
}

TEST(Reproduction, SameSeedsSameBytesWhateverTheThreads) {
  ReproductionOptions options;
  options.ur5 = false;  // the KUKA alone keeps this test short; the UR5 path is above
  const std::vector<std::uint64_t> seeds = {5, 6};
  std::string serial;
  {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    serial = reproduction_json(run_reproductions(seeds, options)).dump();
  }
  const std::vector<Reproduction> runs = run_reproductions(seeds, options);
  EXPECT_TRUE(serial == reproduction_json(runs).dump());
  // A seed gives the same numbers alone as among others.
  options.seed = 6;
  const std::vector<Cell> alone = reproduction_cells(run_reproduction(options));
  const std::vector<Cell> among = reproduction_cells(runs[1]);
  ASSERT_EQ(alone.size(), among.size());
  for (std::size_t k = 0; k < alone.size(); ++k) {
    EXPECT_EQ(alone[k].pointer, among[k].pointer);
    EXPECT_TRUE(alone[k].value == among[k].value ||
                (std::isnan(alone[k].value) && std::isnan(among[k].value)))
        << alone[k].pointer;
  }
}

TEST(Reproduction, RejectsAnEmptyRun) {
  ReproductionOptions options;
  options.ur5 = options.lwr4 = false;
  EXPECT_THROW(run_reproduction(options), InputError);
}

}  // namespace
}  // namespace vrreg::experiments
