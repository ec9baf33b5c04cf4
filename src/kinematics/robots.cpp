// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/robots.hpp"

#include <algorithm>
#include <cctype>
#include <numbers>

#include "vrreg/core/units.hpp"

namespace vrreg::kinematics {
namespace {

using units::kPi;

// UR: only d1, a2, a3, d4, d5, d6 differ between models (manufacturer DH tables, metres).
SerialChain make_ur(const char* name, double d1, double a2, double a3, double d4, double d5,
                    double d6) {
  std::vector<DhRow> rows = {
      {0.0, kPi / 2, d1, 0.0}, {a2, 0.0, 0.0, 0.0},      {a3, 0.0, 0.0, 0.0},
      {0.0, kPi / 2, d4, 0.0}, {0.0, -kPi / 2, d5, 0.0}, {0.0, 0.0, d6, 0.0},
  };
  return SerialChain(name, std::move(rows), std::vector<JointLimits>(6, {-2 * kPi, 2 * kPi}));
}

}  // namespace

SerialChain ur3() { return make_ur("ur3", 0.1519, -0.24365, -0.21325, 0.11235, 0.08535, 0.0819); }

SerialChain ur5() { return make_ur("ur5", 0.089159, -0.425, -0.39225, 0.10915, 0.09465, 0.0823); }

SerialChain ur10() { return make_ur("ur10", 0.1273, -0.612, -0.5723, 0.163941, 0.1157, 0.0922); }

SerialChain ur5e() { return make_ur("ur5e", 0.1625, -0.425, -0.3922, 0.1333, 0.0997, 0.0996); }

SerialChain lwr4() {
  const double d[7] = {0.31, 0.0, 0.40, 0.0, 0.39, 0.0, 0.078};
  const double alpha[7] = {kPi / 2, -kPi / 2, -kPi / 2, kPi / 2, kPi / 2, -kPi / 2, 0.0};
  const double limit_deg[7] = {170, 120, 170, 120, 170, 120, 170};
  std::vector<DhRow> rows;
  std::vector<JointLimits> limits;
  for (int i = 0; i < 7; ++i) {
    rows.push_back({0.0, alpha[i], d[i], 0.0});
    const double l = units::deg_to_rad(limit_deg[i]);
    limits.push_back({-l, l});
  }
  return SerialChain("lwr4", std::move(rows), std::move(limits));
}

const std::vector<std::string>& builtin_robot_names() {
  static const std::vector<std::string> names = {"ur3", "ur5", "ur10", "ur5e", "lwr4"};
  return names;
}

std::optional<SerialChain> robot_by_name(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "ur3") return ur3();
  if (lower == "ur5") return ur5();
  if (lower == "ur10") return ur10();
  if (lower == "ur5e") return ur5e();
  if (lower == "lwr4" || lower == "lwr4+" || lower == "lwr") return lwr4();
  return std::nullopt;
}

}  // namespace vrreg::kinematics
