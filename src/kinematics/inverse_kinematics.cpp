#include "vrreg/kinematics/inverse_kinematics.hpp"

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/lwr_ik.hpp"
#include "vrreg/kinematics/ur_ik.hpp"

namespace vrreg::kinematics {

IkResult inverse_kinematics(const SerialChain& chain, const Eigen::Isometry3d& T_base_tcp,
                            std::optional<double> psi_rad, const IkOptions& options) {
  switch (chain.family()) {
    case ChainFamily::kUr:
      return ur_inverse_kinematics(chain, T_base_tcp, options);
    case ChainFamily::kLwr:
      VRREG_THROW_UNLESS(psi_rad.has_value(), "inverse kinematics: robot '"
                                                  << chain.name()
                                                  << "' has 7 joints and needs an arm angle psi");
      return lwr_inverse_kinematics(chain, T_base_tcp, *psi_rad, options);
    case ChainFamily::kGeneric:
      break;
  }
  VRREG_THROW_UNLESS(false, "inverse kinematics: robot '"
                                << chain.name()
                                << "' has neither the UR nor the LWR 4+ structure; no analytic "
                                   "IK applies to its DH table");
  return {};
}

std::optional<ConfigurationLabel> configuration_of(const SerialChain& chain,
                                                   const JointRef& q_rad) {
  switch (chain.family()) {
    case ChainFamily::kUr:
      return ur_configuration(chain, q_rad);
    case ChainFamily::kLwr:
      return lwr_configuration(chain, q_rad);
    case ChainFamily::kGeneric:
      break;
  }
  return std::nullopt;
}

}  // namespace vrreg::kinematics
