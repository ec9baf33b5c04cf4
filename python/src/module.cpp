// SPDX-License-Identifier: Apache-2.0
// The compiled part of `import vrreg` (python/vrreg/__init__.py re-exports it).
#include "bindings.hpp"
#include "vrreg/config.hpp"

PYBIND11_MODULE(_vrreg, m) {
  m.doc() =
      "vrreg: vision-robot registration with NIST's RRBC correction. Positions are (N, 3) numpy "
      "arrays in metres (sensor frame X, robot frame Y, Y ~ R X + tau, paper Eq. 2).";
  m.attr("__version__") = VRREG_VERSION_STRING;
  using namespace vrreg::python;
  bind_errors(m);
  bind_model(m);
  bind_io(m);
  bind_results(m);
  bind_pipeline(m);
  bind_metrics(m);
  bind_kinematics(m);
  bind_planning(m);
  bind_simulation(m);
  bind_experiments(m);
  bind_timing(m);
  bind_hand_eye(m);
  bind_monitoring(m);
}
