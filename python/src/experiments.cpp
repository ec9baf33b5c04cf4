// SPDX-License-Identifier: Apache-2.0
// `vrreg reproduce` from Python: the paper's experiments on the simulated test beds, as the
// reproduce.json text (vrreg.reproduce parses it into a dict).
#include "bindings.hpp"
#include "vrreg/experiments/reproduction.hpp"
#include "vrreg/experiments/reproduction_json.hpp"

namespace vrreg::python {

void bind_experiments(py::module_& m) {
  m.def(
      "_reproduce_json",
      [](std::uint64_t seed, bool ur5, bool lwr4) {
        experiments::ReproductionOptions options;
        options.ur5 = ur5;
        options.lwr4 = lwr4;
        std::string text;
        {
          py::gil_scoped_release nogil;
          const std::vector<experiments::Reproduction> runs =
              experiments::run_reproductions({seed}, options);
          text = experiments::reproduction_json(runs).dump();
        }
        return text;
      },
      py::arg("seed"), py::arg("ur5"), py::arg("lwr4"),
      "reproduce.json of one seed as text (what `vrreg reproduce --seed N --json` prints).");
}

}  // namespace vrreg::python
