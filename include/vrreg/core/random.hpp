// SPDX-License-Identifier: Apache-2.0
#pragma once
// Seeded random numbers that give the same bytes on every platform: std::normal_distribution is
// implementation-defined, so the Gaussian is drawn here from the raw 64-bit engine.
#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <string>

namespace vrreg {

/// Deterministic generator: mt19937_64 plus portable uniform and Gaussian draws.
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed), seed_(seed) {}

  [[nodiscard]] std::uint64_t seed() const { return seed_; }
  /// Uniform in [0, 1) with 53 random bits.
  double uniform();
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Standard normal (Marsaglia polar method).
  double normal();
  /// Normal with the given standard deviation.
  double normal(double sigma) { return sigma * normal(); }
  /// Three independent normals with the same standard deviation (per axis).
  Eigen::Vector3d normal3(double sigma) { return {normal(sigma), normal(sigma), normal(sigma)}; }
  /// Uniform integer in [0, n).
  std::uint64_t below(std::uint64_t n);
  /// A random rotation, uniform on SO(3) (unit quaternion from four normals).
  Eigen::Matrix3d rotation();
  /// A new independent stream derived from this seed and a stream index (for parallel work).
  [[nodiscard]] static Random stream(std::uint64_t seed, std::uint64_t index);

 private:
  std::mt19937_64 engine_{};
  std::uint64_t seed_{};
  bool has_spare_ = false;
  double spare_ = 0.0;
};

/// Throws InputError naming `what` unless the `count` seeds first, first + 1, ... all fit in 64
/// bits: a run of seeds past 2^64 - 1 would wrap to 0 and repeat seeds (or never end).
void check_seed_run(std::uint64_t first, std::uint64_t count, const std::string& what);

}  // namespace vrreg
