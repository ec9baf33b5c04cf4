// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/arm_configuration.hpp"

#include <cmath>
#include <numbers>

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/ur_ik.hpp"

namespace vrreg::planning {
namespace {

using kinematics::ChainFamily;
using kinematics::IkResult;

IkResult all_solutions(const kinematics::SerialChain& chain, const Eigen::Vector3d& point_base_m,
                       const ArmConfigurationOptions& options, bool apply_limits) {
  kinematics::IkOptions ik;
  ik.apply_joint_limits = apply_limits;
  return kinematics::inverse_kinematics(chain, tcp_pose(point_base_m, options), options.psi_rad,
                                        ik);
}

JointChoice from_result(const kinematics::SerialChain& chain, const IkResult& r,
                        const kinematics::JointRef* reference, kinematics::JointNorm norm) {
  JointChoice choice;
  choice.status = r.status;
  choice.message = r.message;
  if (!r.ok() || r.solutions.empty()) {
    if (choice.message.empty()) choice.message = "no IK solution";
    if (choice.status == kinematics::IkStatus::kOk) {
      choice.status = kinematics::IkStatus::kOutsideLimits;
    }
    return choice;
  }
  const kinematics::IkSolution& s = r.solutions.front();
  choice.q_rad = s.q_rad;
  choice.config = s.config;
  if (reference != nullptr)
    choice.distance_rad =
        kinematics::joint_distance(s.q_rad, *reference, norm, kinematics::JointKinds(chain));
  return choice;
}

}  // namespace

Eigen::Matrix3d tool_pointing_down() {
  return Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
}

void ArmConfigurationOptions::validate(const kinematics::SerialChain& chain) const {
  VRREG_THROW_UNLESS(kinematics::rotation_error(R_base_tcp) <= 1e-6,
                     "arm configuration: the tool orientation is not a proper rotation");
  VRREG_THROW_UNLESS(std::isfinite(psi_rad), "arm configuration: psi is not finite");
  VRREG_THROW_UNLESS(chain.family() != ChainFamily::kGeneric,
                     "arm configuration: robot '"
                         << chain.name()
                         << "' has neither the UR nor the LWR 4+ structure (no analytic IK)");
  if (home_q_rad) chain.check_joints(*home_q_rad, "arm configuration: home joints");
}

Eigen::Isometry3d tcp_pose(const Eigen::Vector3d& point_base_m,
                           const ArmConfigurationOptions& options) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = options.R_base_tcp;
  t.translation() = point_base_m;
  return t;
}

JointChoice part_joints(const kinematics::SerialChain& chain, const Eigen::Vector3d& point_base_m,
                        const ArmConfigurationOptions& options) {
  if (options.home_q_rad) return nearest_joints(chain, point_base_m, *options.home_q_rad, options);
  // Solutions come ordered by configuration index, shifted into the limits: take the first.
  return from_result(chain, all_solutions(chain, point_base_m, options, true), nullptr,
                     options.norm);
}

JointChoice nearest_joints(const kinematics::SerialChain& chain,
                           const Eigen::Vector3d& point_base_m,
                           const kinematics::JointRef& reference_q_rad,
                           const ArmConfigurationOptions& options) {
  // All branches without the limits, then each moved to its 2 pi shift nearest the reference
  // within the limits, as a controller would command it.
  chain.check_joints(reference_q_rad, "nearest joints: reference");
  const IkResult nearest =
      chain.family() == ChainFamily::kUr
          ? kinematics::ur_inverse_kinematics_nearest(chain, tcp_pose(point_base_m, options),
                                                      reference_q_rad, options.norm)
          : kinematics::nearest_solution(chain, all_solutions(chain, point_base_m, options, false),
                                         reference_q_rad, options.norm);
  return from_result(chain, nearest, &reference_q_rad, options.norm);
}

}  // namespace vrreg::planning
