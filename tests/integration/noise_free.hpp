#pragma once
// The test bed's tracker without noise: what a perfect correction would leave is then exact.
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::testing {

/// Only the tracker's systematic part of the test bed's default errors, noise set to zero.
inline simulation::TestbedErrorModel noise_free_tracker_only(const simulation::Testbed& testbed) {
  simulation::TestbedErrorModel e;
  e.tracker = testbed.default_errors.tracker;
  e.tracker.noise_sigma_m.setZero();
  return e;
}

}  // namespace vrreg::testing
