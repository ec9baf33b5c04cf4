// SPDX-License-Identifier: Apache-2.0
// The robust check on a few simulated A1 cells (the full rates: vrreg robust-study, docs/outliers.md).
#include "vrreg/experiments/robust_study.hpp"

#include <gtest/gtest.h>

namespace vrreg::experiments {
namespace {

TEST(RobustStudy, FindsPlantedFiducialsOnAFewCellsAndKeepsTheCleanOnes) {
  RobustStudyOptions options;
  options.seeds = 3;
  const RobustStudy study = robust_study(options);
  ASSERT_EQ(study.cells.size(), 12u);
  int clean_cells = 0, clean_kept = 0;
  for (const RobustStudyCell& c : study.cells) {
    SCOPED_TRACE(std::string(to_string(c.scenario)) + ", seed " + std::to_string(c.seed));
    if (c.scenario == RobustScenario::kSwapped || c.scenario == RobustScenario::kDisplaced2mm) {
      EXPECT_TRUE(c.found);
    }
    if (c.scenario != RobustScenario::kClean) continue;
    ++clean_cells;
    clean_kept += c.good_rejected == 0 ? 1 : 0;
    // Loose: the target is 2 %; nothing rejected means the very same model.
    EXPECT_LT(c.robust_cor_rms_t_m, 1.05 * c.plain_cor_rms_t_m);
  }
  EXPECT_GE(clean_kept, clean_cells - 1);
  int found_1mm = 0;
  for (const RobustStudyCell& c : study.cells) {
    found_1mm += c.scenario == RobustScenario::kDisplaced1mm && c.found ? 1 : 0;
  }
  EXPECT_GE(found_1mm, 2);
  EXPECT_NE(robust_study_text(study).find("2 swapped"), std::string::npos);
}

TEST(RobustStudy, SameOptionsSameNumbers) {
  RobustStudyOptions options;
  options.seeds = 2;
  options.first_seed = 7;
  EXPECT_EQ(robust_study_text(robust_study(options)), robust_study_text(robust_study(options)));
}

}  // namespace
}  // namespace vrreg::experiments
