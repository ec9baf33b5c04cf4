// SPDX-License-Identifier: Apache-2.0
// Every public Options struct outside the front door takes C++20 designated initialisers naming
// one member, under the project's -Wall -Wextra -Werror (GCC's missing-field-initializers fires
// on a member without a default): the others keep their defaults.
#include <gtest/gtest.h>

#include "vrreg/experiments/beyond_paper.hpp"
#include "vrreg/experiments/distance_sweep.hpp"
#include "vrreg/experiments/reproduction.hpp"
#include "vrreg/experiments/robust_study.hpp"
#include "vrreg/experiments/rrbc_run.hpp"
#include "vrreg/experiments/testbed_calibration.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"
#include "vrreg/metrics/rigid_body_sampled.hpp"
#include "vrreg/planning/arm_configuration.hpp"
#include "vrreg/planning/plan.hpp"
#include "vrreg/planning/robot_program.hpp"
#include "vrreg/registration/marker_offset.hpp"
#include "vrreg/registration/rigid.hpp"
#include "vrreg/registration/robust.hpp"
#include "vrreg/simulation/acquisition.hpp"

namespace vrreg {
namespace {

TEST(DesignatedInitialisers, NameOneMemberAndKeepTheOtherDefaults) {
  const RegistrationOptions registration{.estimate_scale = true};
  EXPECT_TRUE(registration.estimate_scale);
  EXPECT_EQ(registration.collinearity_tolerance, RegistrationOptions{}.collinearity_tolerance);
  const io::CsvReadOptions csv{.require_robot = false};
  EXPECT_FALSE(csv.require_robot);
  EXPECT_EQ(csv.max_line_bytes, io::CsvReadOptions{}.max_line_bytes);

  // Each of these compiles only if every member has a default (the warning is an error here).
  [[maybe_unused]] const planning::ArmConfigurationOptions arm{.R_base_tcp = {}};
  [[maybe_unused]] const planning::PlanOptions plan{.halfwidth_m = 0.01};
  [[maybe_unused]] const planning::ProgramOptions program{.repeats = 2};
  [[maybe_unused]] const RobustRegistrationOptions robust{.registration = {}};
  [[maybe_unused]] const MarkerOffsetOptions marker{.min_orientation_spread = 0.05};
  [[maybe_unused]] const SigmaLOptions sigma_l{.exact_max_points = 100};
  [[maybe_unused]] const kinematics::IkOptions ik{.apply_joint_limits = false};
  [[maybe_unused]] const kinematics::JointErrorModelOptions joint{.joint_degrees = {2}};
  [[maybe_unused]] const experiments::ReproductionOptions reproduction{.seed = 2};
  [[maybe_unused]] const experiments::RobustStudyOptions study{.seeds = 2};
  [[maybe_unused]] const experiments::DistanceSweepOptions sweep{.cube_edges_m = {0.05}};
  [[maybe_unused]] const experiments::BeyondOptions beyond{.seed = 2};
  [[maybe_unused]] const experiments::CalibrationOptions calibration{.seeds = {}};
  [[maybe_unused]] const experiments::RrbcRunOptions run{.interpolation = {}};
  [[maybe_unused]] const simulation::SimulationOptions simulation{.seed = 2};
}

}  // namespace
}  // namespace vrreg
