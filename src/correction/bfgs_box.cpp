// SPDX-License-Identifier: Apache-2.0
#include "bfgs_box.hpp"

#include <cmath>
#include <limits>

namespace vrreg::detail {
namespace bfgs_box {

/// Gradient with the components that push out of the box at an active bound zeroed.
Eigen::VectorXd projected(const Eigen::VectorXd& x, const Eigen::VectorXd& g,
                          const Eigen::VectorXd& lower, const Eigen::VectorXd& upper) {
  Eigen::VectorXd p = g;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if ((x(i) <= lower(i) && g(i) > 0.0) || (x(i) >= upper(i) && g(i) < 0.0)) {
      p(i) = 0.0;
    }
  }
  return p;
}

}  // namespace bfgs_box

BoxMinimum minimise_bfgs_box(const BoxObjective& f, const Eigen::VectorXd& x0,
                             const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                             int max_iterations, double gradient_tolerance) {
  const Eigen::Index n = x0.size();
  BoxMinimum best;
  best.x = x0.cwiseMax(lower).cwiseMin(upper);
  Eigen::VectorXd g(n);
  best.value = f(best.x, &g);
  best.evaluations = 1;
  if (!std::isfinite(best.value)) {
    best.value = std::numeric_limits<double>::infinity();
    return best;
  }
  Eigen::MatrixXd h = Eigen::MatrixXd::Identity(n, n);  // inverse Hessian estimate
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    const Eigen::VectorXd pg = bfgs_box::projected(best.x, g, lower, upper);
    if (pg.cwiseAbs().maxCoeff() < gradient_tolerance) {
      break;
    }
    Eigen::VectorXd direction = -(h * pg);
    if (direction.dot(pg) >= 0.0) {  // not a descent direction: restart from steepest descent
      h.setIdentity();
      direction = -pg;
    }
    // Cap the step at 2 in log-parameters (a factor e^2), then backtrack (Armijo).
    const double length = direction.cwiseAbs().maxCoeff();
    double t = length > 2.0 ? 2.0 / length : 1.0;
    Eigen::VectorXd x_new(n);
    Eigen::VectorXd g_new(n);
    double value_new = std::numeric_limits<double>::infinity();
    bool accepted = false;
    for (int halving = 0; halving < 30; ++halving, t *= 0.5) {
      x_new = (best.x + t * direction).cwiseMax(lower).cwiseMin(upper);
      value_new = f(x_new, &g_new);
      ++best.evaluations;
      if (std::isfinite(value_new) && value_new <= best.value + 1e-4 * pg.dot(x_new - best.x)) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      break;
    }
    const Eigen::VectorXd s = x_new - best.x;
    const Eigen::VectorXd y = g_new - g;
    const double improvement = best.value - value_new;
    best.x = x_new;
    best.value = value_new;
    g = g_new;
    const double sy = s.dot(y);
    if (sy > 1e-12 * s.norm() * y.norm()) {
      const double rho = 1.0 / sy;
      const Eigen::MatrixXd v = Eigen::MatrixXd::Identity(n, n) - rho * y * s.transpose();
      h = v.transpose() * h * v + rho * s * s.transpose();
    }
    if (improvement < 1e-10 * (1.0 + std::abs(best.value))) {
      break;
    }
  }
  return best;
}

}  // namespace vrreg::detail
