// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared fixtures of the simulation tests: error models with parts switched off.
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::testing {

/// A robot that lands exactly where commanded and a tracker without noise.
inline simulation::TestbedErrorModel perfect_errors(const simulation::Testbed& testbed) {
  simulation::TestbedErrorModel e;
  e.tracker = testbed.default_errors.tracker;
  e.tracker.noise_sigma_m.setZero();
  return e;
}

}  // namespace vrreg::testing
