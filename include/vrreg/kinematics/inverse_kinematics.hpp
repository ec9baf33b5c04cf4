#pragma once
// One entry point over the analytic solvers, chosen by the chain's family.
#include <optional>

#include <Eigen/Geometry>

#include "vrreg/kinematics/configuration_label.hpp"
#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// Every IK solution of `T_base_tcp` (base frame, m): UR chains ignore `psi_rad`; LWR chains
/// need it (throws InputError when absent); generic chains throw InputError.
IkResult inverse_kinematics(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                            std::optional<double> psi_rad = std::nullopt,
                            const IkOptions& options = {});

/// The configuration label of `q_rad` [rad]; empty for a generic chain.
std::optional<ConfigurationLabel> configuration_of(const SerialChain& chain, const JointRef& q_rad);

}  // namespace vrreg::kinematics
