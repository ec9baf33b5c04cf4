// SPDX-License-Identifier: Apache-2.0
#pragma once
// Unit conversions. Only io/ and the command line convert; the library is SI throughout.
#include <numbers>

namespace vrreg::units {

inline constexpr double kPi = std::numbers::pi;

inline constexpr double kMetresPerMillimetre = 1e-3;
inline constexpr double kMillimetresPerMetre = 1e3;
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

constexpr double mm_to_m(double mm) { return mm * kMetresPerMillimetre; }
constexpr double m_to_mm(double m) { return m * kMillimetresPerMetre; }
constexpr double deg_to_rad(double deg) { return deg * kRadiansPerDegree; }
constexpr double rad_to_deg(double rad) { return rad * kDegreesPerRadian; }

}  // namespace vrreg::units
