// SPDX-License-Identifier: Apache-2.0
// The metrics behind register's and evaluate's numbers, for arrays a user already has: sigma_L
// (Eq. 1), sigma_noise and rho (Eq. 9), gamma and N_bad (section 5.1).
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "vrreg/metrics/improvement.hpp"
#include "vrreg/metrics/noise.hpp"
#include "vrreg/metrics/rigid_body.hpp"

namespace vrreg::python {

void bind_metrics(py::module_& m) {
  m.def(
      "rigid_body_statistics",
      [](const py::object& sensor, const py::object& robot) {
        const Points3 x = points_from(sensor, "sensor");
        const Points3 y = points_from(robot, "robot");
        RigidBodyStatistics s;
        {
          py::gil_scoped_release nogil;
          s = rigid_body_statistics(x, y);
        }
        py::dict d;
        d["pairs"] = s.pairs;
        d["mean"] = s.mean_m;
        d["sigma_l"] = s.sigma_l_m;
        d["min"] = s.min_m;
        d["max"] = s.max_m;
        return d;
      },
      py::arg("sensor"), py::arg("robot"),
      "L_ij = ||X_i - X_j|| - ||Y_i - Y_j|| over all pairs (Eq. 1): dict of pairs, mean, sigma_l, "
      "min, max [m]. sensor, robot: (N, 3) positions in METRES, sensor and robot frame.");
  m.def("sigma_noise", &sigma_noise_m, py::arg("sigma_opt"), py::arg("sigma_rep"),
        "sqrt(sigma_opt^2 + sigma_rep^2) (Eq. 9) [m]; both in metres.");
  m.def("rho", &vrreg::rho, py::arg("sigma_l"), py::arg("sigma_noise"),
        "sigma_L / sigma_noise (section 5.1): RRBC is expected to help when > 2.5. Metres in.");
  m.attr("RHO_THRESHOLD") = kRhoThreshold;
  m.def(
      "improvement",
      [](const py::object& unc_tre, const py::object& cor_tre) {
        const Eigen::VectorXd unc = vector_from(unc_tre, "unc_tre");
        const Eigen::VectorXd cor = vector_from(cor_tre, "cor_tre", unc.size());
        ImprovementSummary s = summarize_improvement(unc, cor);
        py::dict d;
        d["n_targets"] = s.n_targets;
        d["unc_rms_t"] = s.unc_rms_t_m;
        d["cor_rms_t"] = s.cor_rms_t_m;
        d["gamma"] = s.gamma;
        d["n_bad"] = s.n_bad;
        d["bad_targets"] = s.bad_targets;
        d["delta_tre"] = to_numpy(std::move(s.delta_tre_m));
        return d;
      },
      py::arg("unc_tre"), py::arg("cor_tre"),
      "RMS_T both ways (Eq. 4), gamma = (unc - cor) / unc, N_bad and the Delta TRE where it "
      "improved (section 5.1) from per-target TRE [m], same order: a dict, metres.");
}

}  // namespace vrreg::python
