// SPDX-License-Identifier: Apache-2.0
// Octuplet corners measured more than once (dataset B: neighbouring cubes share corners): the
// reading nearest the target's in the visiting order is taken; without a sequence, an error.
#include <gtest/gtest.h>

#include "vrreg/core/check.hpp"
#include "vrreg/correction/octuplet.hpp"
#include "vrreg_test.hpp"

namespace vrreg {
namespace {

// Two copies of a cube's corners (a = 10 mm around the origin): copy 0 read at lines 10..17,
// copy 1 at lines 100..107.
Points3 two_copies(std::vector<std::size_t>& sequence) {
  Points3 p(3, 16);
  for (int copy = 0; copy < 2; ++copy) {
    for (int c = 0; c < 8; ++c) {
      p.col(copy * 8 + c) = 0.005 * Eigen::Vector3d((c & 1) ? 1 : -1, (c & 2) ? 1 : -1,
                                                    (c & 4) ? 1 : -1);
      sequence.push_back(static_cast<std::size_t>(copy == 0 ? 10 + c : 100 + c));
    }
  }
  return p;
}

TEST(OctupletSequence, TakesTheReadingNearestTheTargetInSequence) {
  std::vector<std::size_t> sequence;
  const Points3 p = two_copies(sequence);
  const OctupletStencils stencils(p, 0.01, 1e-6, sequence);
  const Stencil early = stencils.stencil(Eigen::Vector3d::Zero(), 9);
  const Stencil late = stencils.stencil(Eigen::Vector3d::Zero(), 99);
  ASSERT_EQ(early.status, StencilStatus::kOk);
  ASSERT_EQ(late.status, StencilStatus::kOk);
  for (std::size_t c = 0; c < 8; ++c) {
    EXPECT_EQ(early.fiducial[c], static_cast<Eigen::Index>(c));
    EXPECT_EQ(late.fiducial[c], static_cast<Eigen::Index>(8 + c));
    EXPECT_DOUBLE_EQ(early.weight[c], 0.125);
  }
}

TEST(OctupletSequence, DuplicatesWithoutASequenceAreAnError) {
  std::vector<std::size_t> sequence;
  const Points3 p = two_copies(sequence);
  EXPECT_THROW(OctupletStencils(p, 0.01, 1e-6), InputError);
  sequence.pop_back();
  EXPECT_THROW(OctupletStencils(p, 0.01, 1e-6, sequence), InputError);
}

}  // namespace
}  // namespace vrreg
