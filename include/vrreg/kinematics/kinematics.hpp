// SPDX-License-Identifier: Apache-2.0
#pragma once
// Everything of the kinematics module in one include.
#include "vrreg/kinematics/configuration_label.hpp"
#include "vrreg/kinematics/dh.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"
#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/lwr_ik.hpp"
#include "vrreg/kinematics/lwr_psi_intervals.hpp"
#include "vrreg/kinematics/marker_partials.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/kinematics/ur_ik.hpp"
