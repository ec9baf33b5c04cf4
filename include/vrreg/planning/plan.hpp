// SPDX-License-Identifier: Apache-2.0
#pragma once
// Procedure 1, "where to measure" (paper section 6, Fig. 16): for M part points whose placement
// varies within +-S, a cube of fiducials on a grid of spacing A around each (fiducial_grid.hpp),
// the d_min > 2.5 sigma_noise check (Eq. 9), an arm configuration for every location nearest the
// one its part point is reached in (arm_configuration.hpp), and a visiting order: a serpentine in
// each cube (serpentine.hpp), the part point visited inside it, cubes ordered to keep the travel
// between them short (cube_tour.hpp).
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/kinematics/configuration_label.hpp"
#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/planning/approach.hpp"
#include "vrreg/planning/arm_configuration.hpp"
#include "vrreg/planning/dmin_criterion.hpp"
#include "vrreg/planning/fiducial_grid.hpp"

namespace vrreg::planning {

/// A part point (Fig. 16 target): a feature whose position must be known accurately.
struct PartPoint {
  std::string name{};  ///< label; its fiducials are "<name>.f<ix>-<iy>-<iz>" (grid indices)
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();  ///< nominal position, robot base frame [m]
};

/// What to plan.
struct PlanOptions {
  double halfwidth_m = 0.0;                  ///< placement tolerance S [m]
  double spacing_m = 0.0;                    ///< grid spacing A [m]
  double sigma_noise_m = kPaperSigmaNoiseM;  ///< noise level for Eq. 9 [m]
  bool force = false;                        ///< plan even when Eq. 9 fails
  ArmConfigurationOptions arm{};             ///< tool orientation, norm, psi, home joints
  long long max_locations = 100'000;         ///< refuse larger plans (a robot visits each one)
  /// One approach direction per joint: a via point before every location (approach.hpp); empty
  /// direction = off (the arm moves from location to location directly).
  ApproachOptions approach{};
  /// Throws InputError on a bad field (see the members) for `chain`.
  void validate(const kinematics::SerialChain& chain) const;
};

/// Outcome of planning.
enum class PlanStatus { kOk, kUnreachable };

/// Lower-case name of a status ("ok", "unreachable").
const char* to_string(PlanStatus status);

/// One location of the plan, in visiting order.
struct PlannedLocation {
  std::string point{};                                   ///< label (part name for the target)
  Role role = Role::kFiducial;                           ///< the part point itself is the target
  int part = 0;                                          ///< index of its part point
  Eigen::Vector3i grid_index = Eigen::Vector3i::Zero();  ///< node indices; kCentreIndex: target
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();     ///< TCP position, robot base frame [m]
  kinematics::JointVector q_rad{};                       ///< commanded joints [rad]
  kinematics::ConfigurationLabel config{};
  double joint_distance_rad = 0.0;  ///< to its part point's joints (options.arm.norm) [rad]
  /// The joint-space via point the arm moves to just before this location, never measured: every
  /// joint then arrives moving in the plan's approach direction (approach.hpp). Empty: none.
  std::optional<kinematics::JointVector> via_q_rad{};
  Eigen::Vector3d via_robot_m = Eigen::Vector3d::Zero();  ///< nominal TCP at via_q_rad [m]
};

/// Per part point: its cube and configuration.
struct PartPlan {
  std::string name{};
  Eigen::Vector3d robot_m = Eigen::Vector3d::Zero();  ///< robot base frame [m]
  long long n_fiducials = 0;
  double d_min_m = 0.0;  ///< to its 8 nearest fiducials [m]
  double d_max_m = 0.0;  ///< to its farthest fiducials [m]
  bool reachable = false;
  kinematics::JointVector q_rad{};  ///< joints of the part point [rad] (when reachable)
  kinematics::ConfigurationLabel config{};
  long long n_other_config = 0;         ///< fiducials whose configuration label differs
  double max_joint_distance_rad = 0.0;  ///< largest fiducial-to-part joint distance [rad]
  int visit_rank = -1;                  ///< position of its cube in the visiting order
};

/// A location without joints, and why.
struct UnreachableLocation {
  std::string point{};
  std::string reason{};
  int part = -1;  ///< index of its part point in the input
};

/// The plan, or which locations cannot be reached (then `locations` is empty).
struct PlanResult {
  PlanStatus status = PlanStatus::kOk;
  std::string message{};  ///< why not ok (names the first unreachable locations)
  CubeGeometry cube{};
  DminCheck dmin{};
  std::vector<PartPlan> parts{};                   ///< in input order
  std::vector<PlannedLocation> locations{};        ///< in visiting order
  std::vector<UnreachableLocation> unreachable{};  ///< every location without joints
  std::vector<std::array<int, 2>> overlapping{};   ///< part pairs whose cubes overlap or touch
  double within_cubes_m = 0.0;                     ///< travel inside the cubes [m]
  double between_cubes_m = 0.0;                    ///< travel between cubes, planned order [m]
  double naive_between_cubes_m = 0.0;  ///< the same for input order, serpentine variant 0 [m]
  [[nodiscard]] bool ok() const { return status == PlanStatus::kOk; }
};

/// Plans Procedure 1 (section 6) for `parts` on `chain` (UR or LWR 4+ structure). Throws
/// InputError on bad options or parts (none, duplicate names, non-finite positions), when Eq. 9
/// fails without options.force, or when the plan exceeds options.max_locations; unreachable
/// locations are a status in the result.
PlanResult make_plan(const kinematics::SerialChain& chain, const std::vector<PartPoint>& parts,
                     const PlanOptions& options);

}  // namespace vrreg::planning
