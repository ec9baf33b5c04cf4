// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/random.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "vrreg/core/check.hpp"

namespace vrreg {

void check_seed_run(std::uint64_t first, std::uint64_t count, const std::string& what) {
  constexpr std::uint64_t kLast = std::numeric_limits<std::uint64_t>::max();
  VRREG_THROW_UNLESS(count == 0 || first <= kLast - (count - 1),
                     what << ": " << count << " seeds from " << first
                          << " pass 2^64 - 1 = " << kLast << " (the largest seed)");
}

double Random::uniform() {
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

double Random::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  double u = 0.0;
  double v = 0.0;
  double s = 0.0;
  do {
    u = 2.0 * uniform() - 1.0;
    v = 2.0 * uniform() - 1.0;
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double factor = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = v * factor;
  has_spare_ = true;
  return u * factor;
}

std::uint64_t Random::below(std::uint64_t n) {
  // Rejection keeps it unbiased and portable (no std::uniform_int_distribution).
  const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);
  std::uint64_t x = 0;
  do {
    x = engine_();
  } while (x >= limit);
  return x % n;
}

Eigen::Matrix3d Random::rotation() {
  Eigen::Quaterniond q(normal(), normal(), normal(), normal());
  q.normalize();
  return q.toRotationMatrix();
}

Random Random::stream(std::uint64_t seed, std::uint64_t index) {
  // SplitMix64 of (seed, index): well-separated seeds for parallel streams.
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (index + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return Random(z);
}

}  // namespace vrreg
