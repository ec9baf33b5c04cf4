// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared test helpers: EXPECT_EIGEN_NEAR and seeded point generators.
#include <cstdlib>
#include <sstream>
#include <string>

#include <Eigen/Core>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "vrreg/core/random.hpp"
#include "vrreg/core/types.hpp"

namespace vrreg::testing {

template <typename A, typename B>
::testing::AssertionResult eigen_near(const char* a_expr, const char* b_expr, const char*,
                                      const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b,
                                      double tolerance) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) {
    return ::testing::AssertionFailure() << a_expr << " and " << b_expr << " differ in shape: "
                                         << a.rows() << "x" << a.cols() << " vs " << b.rows()
                                         << "x" << b.cols();
  }
  const double diff = (a - b).cwiseAbs().maxCoeff();
  if (diff <= tolerance) return ::testing::AssertionSuccess();
  std::ostringstream out;
  out.precision(17);
  out << "max |" << a_expr << " - " << b_expr << "| = " << diff << " > " << tolerance << "\n"
      << a_expr << " =\n" << a << "\n" << b_expr << " =\n" << b;
  return ::testing::AssertionFailure() << out.str();
}

/// True when the tests run under the sanitizers (long loops may be shortened there).
inline bool sanitized() { return std::getenv("VRREG_SANITIZED") != nullptr; }

/// Points uniform in a box of half-width `half_m` around `centre_m`.
inline Points3 random_points(Random& rng, int n, double half_m,
                             const Eigen::Vector3d& centre_m = Eigen::Vector3d::Zero()) {
  Points3 p(3, n);
  for (int j = 0; j < n; ++j) {
    for (int a = 0; a < 3; ++a) p(a, j) = centre_m(a) + rng.uniform(-half_m, half_m);
  }
  return p;
}

/// A random rigid transform with translation up to `max_translation_m` per axis.
inline RigidTransform random_transform(Random& rng, double max_translation_m) {
  RigidTransform t;
  t.rotation = rng.rotation();
  for (int a = 0; a < 3; ++a) t.translation_m(a) = rng.uniform(-1, 1) * max_translation_m;
  return t;
}

/// An n x n x n cube of nominal positions [m] at `spacing_m`, node (0,0,0) at (0.3, -0.1, 0.1)
/// plus `offset_m` on every axis (x fastest).
inline Points3 cube_grid_m(int n, double spacing_m, double offset_m = 0.0) {
  Points3 out(3, n * n * n);
  for (int i = 0; i < n * n * n; ++i) {
    out.col(i) = Eigen::Vector3d(0.3, -0.1, 0.1) +
                 (offset_m + spacing_m * Eigen::Array3d(i % n, i / n % n, i / (n * n))).matrix();
  }
  return out;
}

}  // namespace vrreg::testing

#define EXPECT_EIGEN_NEAR(a, b, tol) EXPECT_PRED_FORMAT3(::vrreg::testing::eigen_near, a, b, tol)
#define ASSERT_EIGEN_NEAR(a, b, tol) ASSERT_PRED_FORMAT3(::vrreg::testing::eigen_near, a, b, tol)
