// SPDX-License-Identifier: Apache-2.0
#pragma once
// Acquisition of a dataset on a simulated test bed (paper sections 4.1, 4.2): the controller
// turns each nominal location into joints with the nominal model, the robot lands where its
// actual model and errors put it, and the tracker reads the sphere K times per visit.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/simulation/cell_events.hpp"
#include "vrreg/simulation/dataset_plan.hpp"
#include "vrreg/simulation/robot_error_model.hpp"
#include "vrreg/simulation/testbed.hpp"

namespace vrreg::simulation {

/// What to simulate beyond the test bed and dataset.
struct SimulationOptions {
  std::uint64_t seed = 1;                     ///< decides the robot (DH errors, phases) and noise
  std::optional<TestbedErrorModel> errors{};  ///< empty: the test bed's defaults
  /// Where the tracked marker really sits in the flange frame [m]; empty: where the controller's
  /// tool says (the paper's precision mount). Set it to simulate a cell whose offset is unknown:
  /// the file's robot positions stay the controller's TCP, the tracker sees the real marker.
  std::optional<Eigen::Vector3d> marker_flange_m = std::nullopt;
  /// A rigid body mounted turned against the tool frame it is commanded in: the rotation vector
  /// of its true orientation in the tool frame [rad] (a few tenths of a degree in practice).
  /// Positions are unchanged; empty: mounted exactly.
  std::optional<Eigen::Vector3d> body_mount_rotation_rad = std::nullopt;
  /// Plans: visits of each monitor location (role monitor), read in rounds after the others.
  int monitor_visits = 12;
  /// When this acquisition is made [s after time 0]: the robot has grown by
  /// events.thermal.growth_at(time_s), the tracker is bumped when time_s >= events.bump_time_s,
  /// and the noise is drawn afresh (time 0 draws exactly what it always did).
  double time_s = 0.0;
  CellEvents events{};
};

/// A realistic unknown marker offset for the hand-eye scenario: a marker clamped to the gripper
/// tens of millimetres off the tool axis (35, -25, 85) mm in the flange frame.
inline const Eigen::Vector3d kRealisticMarkerFlangeM{0.035, -0.025, 0.085};

/// One visit of the arm: a location in one arm configuration.
struct SimulatedVisit {
  int location = 0;  ///< index into SimulatedDataset::locations
  int config = 0;    ///< LWR grid: label 1..4 in the IK module's order; plan: its config; else 0
  kinematics::JointVector q_rad{};  ///< commanded joints, as the controller reports them [rad]
  Eigen::Vector3d tcp_m = Eigen::Vector3d::Zero();  ///< true TCP position of the visit [m, base]
  int round = -1;  ///< monitor locations: which of their visits this is; -1 for the others
  /// The marker's commanded orientation (the nominal model at the commanded joints) and its true
  /// one (the actual model at the actual joints), base frame; set with a rigid-body tracker.
  Eigen::Matrix3d R_commanded = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d R_true = Eigen::Matrix3d::Identity();
  /// Joints the arm is sent to just before, never read: a via point that sets the direction each
  /// joint arrives from (lost motion) [rad]; empty: moved to directly.
  std::optional<kinematics::JointVector> via_q_rad{};
};

/// One tracker reading of a visit.
struct SimulatedReading {
  int visit = 0;                                       ///< index into SimulatedDataset::visits
  int repeat = 0;                                      ///< 0..K-1
  Eigen::Vector3d sensor_m = Eigen::Vector3d::Zero();  ///< measured position, sensor frame [m]
  /// Measured orientation, sensor frame: with a rigid-body tracker (rigid_body_radius_m > 0).
  std::optional<Eigen::Quaterniond> q_sensor_marker{};
};

/// A simulated dataset: locations, visits and readings in visiting order, plus the truth.
struct SimulatedDataset {
  std::string testbed{};  ///< "ur5" or "lwr4"
  Dataset dataset = Dataset::kA1;
  std::uint64_t seed = 0;
  TestbedErrorModel errors{};       ///< the error model used
  RobotErrors robot{};              ///< the robot the seed drew
  RigidTransform T_robot_sensor{};  ///< the true tracker pose
  /// The true marker position in the flange frame [m] when options gave one; empty: the tool's.
  std::optional<Eigen::Vector3d> marker_flange_m{};
  std::optional<Eigen::Vector3d> body_mount_rotation_rad{};  ///< SimulationOptions'
  double sigma_rep_spec_m = 0.0;  ///< the robot's specified repeatability
  double time_s = 0.0;            ///< when it was acquired (SimulationOptions::time_s)
  CellEvents events{};            ///< what had happened by then
  bool has_config = false;  ///< visits carry configuration labels (LWR grid; plans with config)
  std::vector<PlannedLocation> locations{};
  std::vector<SimulatedVisit> visits{};
  std::vector<SimulatedReading> readings{};
};

/// Simulates `dataset` on `testbed`. Throws InputError for a dataset of the other test bed or an
/// invalid error model. Same inputs, same result, bit for bit (vrreg::Random streams only).
SimulatedDataset simulate_dataset(const Testbed& testbed, Dataset dataset,
                                  const SimulationOptions& options = {});

/// Per-visit mean of the readings [m, sensor frame], one column per visit.
Points3 visit_means_m(const SimulatedDataset& data);

}  // namespace vrreg::simulation
