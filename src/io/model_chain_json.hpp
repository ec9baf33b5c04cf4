// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to io: a serial chain in a model file (the hand-eye flange robot, the joint-space
// field model's robot): name, DH rows, joint limits, base and tool transforms.
#include <nlohmann/json.hpp>
#include <string>

#include "json_fields.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::io::detail {

/// {"name", "dh_a_m_alpha_rad_d_m_theta_offset_rad", "joint_limits_rad", "T_base_dh0_m"
/// [, "T_flange_tcp_m" when with_tool]}; `what` names the member in errors.
nlohmann::ordered_json chain_json(const kinematics::SerialChain& chain, bool with_tool,
                                  const char* what);

/// Reads what chain_json writes at key path `path` (the tool is optional: identity when absent).
kinematics::SerialChain read_chain(const nlohmann::json& robot, const std::string& path,
                                   const JsonFields& f);

}  // namespace vrreg::io::detail
