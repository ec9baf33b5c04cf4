// SPDX-License-Identifier: Apache-2.0
#pragma once
// A small deterministic quasi-Newton minimiser (BFGS, projected onto a box, Armijo
// backtracking) for the handful of hyperparameters of the field models.
#include <Eigen/Core>
#include <functional>

namespace vrreg::detail {

/// f(x, gradient) -> value; gradient may be nullptr. +infinity or NaN marks an infeasible x.
using BoxObjective = std::function<double(const Eigen::VectorXd&, Eigen::VectorXd*)>;

struct BoxMinimum {
  Eigen::VectorXd x;
  double value = 0.0;
  int evaluations = 0;
};

/// Minimises f over lower <= x <= upper from x0 (clamped into the box). Stops after
/// max_iterations, when the projected gradient's largest entry is below gradient_tolerance,
/// or when a step improves f by less than 1e-10 (1 + |f|).
[[nodiscard]] BoxMinimum minimise_bfgs_box(const BoxObjective& f, const Eigen::VectorXd& x0,
                                           const Eigen::VectorXd& lower,
                                           const Eigen::VectorXd& upper, int max_iterations,
                                           double gradient_tolerance);

}  // namespace vrreg::detail
