// SPDX-License-Identifier: Apache-2.0
#pragma once
// A robot file for the command-line tests: the UR5's DH table under another name.
namespace vrreg::testing {

inline const char* const kUr5RobotYaml =
    "name: my-ur5\ndh:\n"
    "  - {a_m: 0, alpha_deg: 90, d_m: 0.089159}\n"
    "  - {a_m: -0.425, alpha_deg: 0, d_m: 0}\n"
    "  - {a_m: -0.39225, alpha_deg: 0, d_m: 0}\n"
    "  - {a_m: 0, alpha_deg: 90, d_m: 0.10915}\n"
    "  - {a_m: 0, alpha_deg: -90, d_m: 0.09465}\n"
    "  - {a_m: 0, alpha_deg: 0, d_m: 0.0823}\n";

}  // namespace vrreg::testing
