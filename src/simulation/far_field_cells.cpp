// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/far_field_cells.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/simulation/plan_acquisition.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg/simulation/tracker_model.hpp"

namespace vrreg::simulation {
namespace {

// Streams of one cell's seed: what the tracker's field is, where it stands, the directions of the
// targets and the readings' noise draw independently.
constexpr std::uint64_t kFieldStream = 1;
constexpr std::uint64_t kPoseStream = 2;
constexpr std::uint64_t kDirectionStream = 3;
constexpr std::uint64_t kNoiseStream = 4;

/// A tracker's systematic error at a point [m]: plane waves and an affine part about an origin.
struct TrackerField {
  struct Wave {
    Eigen::Vector3d amplitude_m = Eigen::Vector3d::Zero();
    Eigen::Vector3d wave_per_m = Eigen::Vector3d::Zero();  ///< 2 pi n / lambda
    double phase_rad = 0.0;
  };
  std::array<Wave, 3> waves{};
  Eigen::Matrix3d linear = Eigen::Matrix3d::Zero();
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();

  [[nodiscard]] Eigen::Vector3d error_m(const Eigen::Vector3d& p_m) const {
    Eigen::Vector3d e = linear * (p_m - origin_m);
    for (const Wave& w : waves) e += w.amplitude_m * std::sin(w.wave_per_m.dot(p_m) + w.phase_rad);
    return e;
  }
};

bool has_axis_warp(FarPhysics physics) {
  return physics == FarPhysics::kTrackerAxisWarp ||
         physics == FarPhysics::kTrackerAxisWarpAndScale;
}

bool has_scale(FarPhysics physics) {
  return physics == FarPhysics::kTrackerScale || physics == FarPhysics::kTrackerAxisWarpAndScale;
}

constexpr double kWaveAmplitudeM = 0.1e-3;
constexpr double kScaleLo = 1e-4;
constexpr double kScaleHi = 5e-4;
constexpr double kShearSd = 1e-4;
constexpr double kTrackerDistanceM = 2.0;

Eigen::Vector3d unit_vector(Random& rng) {
  Eigen::Vector3d d(rng.normal(), rng.normal(), rng.normal());
  return d.normalized();
}

TrackerField tracker_field(FarPhysics physics, const Eigen::Vector3d& tracker_m, Random& rng) {
  TrackerField f;
  const double amplitude_m = physics == FarPhysics::kTrackerScale ? 0.2 * kWaveAmplitudeM
                                                                   : kWaveAmplitudeM;
  for (std::size_t k = 0; k < f.waves.size(); ++k) {
    TrackerField::Wave& w = f.waves[k];
    if (has_axis_warp(physics)) {  // component k a wave of coordinate k
      const auto axis = static_cast<Eigen::Index>(k);
      w.amplitude_m = rng.uniform(1.0, 1.5) * kWaveAmplitudeM * Eigen::Vector3d::Unit(axis);
      w.wave_per_m = 2.0 * std::numbers::pi / rng.uniform(0.25, 0.4) * Eigen::Vector3d::Unit(axis);
    } else {
      w.amplitude_m = rng.normal3(amplitude_m / std::sqrt(3.0));
      w.wave_per_m = 2.0 * std::numbers::pi / rng.uniform(0.15, 0.6) * unit_vector(rng);
    }
    w.phase_rad = rng.uniform(0.0, 2.0 * std::numbers::pi);
  }
  if (has_scale(physics)) {
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    f.linear = sign * rng.uniform(kScaleLo, kScaleHi) * Eigen::Matrix3d::Identity();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) f.linear(r, c) += rng.normal(kShearSd);
    }
    f.origin_m = tracker_m;
  }
  return f;
}

// The lattice's nodes about `centre_m`, x fastest.
Points3 lattice_m(const FarFieldCellOptions& o, const Eigen::Vector3d& centre_m) {
  const int n = o.nodes;
  Points3 out(3, n * n * n);
  const double half = 0.5 * (n - 1) * o.spacing_m;
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        out.col(i + n * (j + n * k)) =
            centre_m + Eigen::Vector3d(i * o.spacing_m - half, j * o.spacing_m - half,
                                       k * o.spacing_m - half);
      }
    }
  }
  return out;
}

// A target `distance` lattice sizes from the lattice's box (of half-extent `size_m` / 2 about
// `centre_m`) in direction `u`: the distance along u found by bisection.
Eigen::Vector3d far_point_m(const Eigen::Vector3d& centre_m, double size_m, double distance,
                            const Eigen::Vector3d& u) {
  const double half_m = 0.5 * size_m;
  const double wanted_m = distance * size_m;
  const auto beyond_m = [&](double r) {
    const Eigen::Vector3d p = r * u;
    return (p - p.cwiseMax(Eigen::Vector3d::Constant(-half_m))
                    .cwiseMin(Eigen::Vector3d::Constant(half_m)))
        .norm();
  };
  double lo = 0.0;
  double hi = std::sqrt(3.0) * half_m + wanted_m;  // beyond_m(hi) >= wanted_m
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (beyond_m(mid) < wanted_m ? lo : hi) = mid;
  }
  return centre_m + hi * u;
}

FarFieldCell tracker_cell(const FarFieldCellOptions& o) {
  FarFieldCell cell;
  const Eigen::Vector3d centre_m(0.45, 0.0, 0.25);
  Random pose_rng = Random::stream(o.seed, kPoseStream);
  RigidTransform T_robot_sensor;
  T_robot_sensor.rotation = pose_rng.rotation();
  T_robot_sensor.translation_m = centre_m + kTrackerDistanceM * unit_vector(pose_rng);
  const RigidTransform T_sensor_robot = T_robot_sensor.inverse();
  Random field_rng = Random::stream(o.seed, kFieldStream);
  const TrackerField field = tracker_field(o.physics, T_robot_sensor.translation_m, field_rng);
  Random noise_rng = Random::stream(o.seed, kNoiseStream);
  const auto read = [&](const Eigen::Vector3d& p_m) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int r = 0; r < o.repeats; ++r)
      sum += T_sensor_robot.apply(Eigen::Vector3d(p_m + field.error_m(p_m))) +
             noise_rng.normal3(o.noise_sd_m);
    return Eigen::Vector3d(sum / o.repeats);
  };
  cell.fiducials_robot_m = lattice_m(o, centre_m);
  cell.fiducials_sensor_m.resize(3, cell.fiducials_robot_m.cols());
  for (Eigen::Index j = 0; j < cell.fiducials_robot_m.cols(); ++j)
    cell.fiducials_sensor_m.col(j) = read(cell.fiducials_robot_m.col(j));
  const double size_m = (o.nodes - 1) * o.spacing_m;
  Random direction_rng = Random::stream(o.seed, kDirectionStream);
  const auto m = static_cast<Eigen::Index>(o.distances.size()) * o.directions;
  cell.targets_robot_m.resize(3, m);
  cell.targets_sensor_m.resize(3, m);
  Eigen::Index t = 0;
  for (const double distance : o.distances) {
    for (int d = 0; d < o.directions; ++d, ++t) {
      cell.targets_robot_m.col(t) = far_point_m(centre_m, size_m, distance, unit_vector(direction_rng));
      cell.targets_sensor_m.col(t) = read(cell.targets_robot_m.col(t));
      cell.target_distance.push_back(distance);
    }
  }
  cell.noise_sd_m = o.noise_sd_m / std::sqrt(static_cast<double>(o.repeats));
  return cell;
}

FarFieldCell robot_cell(const FarFieldCellOptions& o) {
  const Testbed testbed = o.physics == FarPhysics::kUr5Robot ? ur5_testbed() : lwr4_testbed();
  const std::optional<double> psi =
      testbed.kind == TestbedKind::kLwr4 ? std::optional<double>(testbed.arm_angle_rad)
                                         : std::nullopt;
  const auto joints_at = [&](const Eigen::Vector3d& p_m) -> std::optional<kinematics::JointVector> {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = testbed.tcp_rotation;
    pose.translation() = p_m;
    const kinematics::IkResult ik =
        kinematics::inverse_kinematics_nearest(testbed.nominal, pose, testbed.home_q_rad, psi);
    if (!ik.ok() || ik.solutions.empty()) return std::nullopt;
    return ik.solutions.front().q_rad;
  };
  std::vector<CommandedLocation> plan;
  const Points3 lattice = lattice_m(o, testbed.volume_centre_m);
  std::optional<kinematics::ConfigurationLabel> label;
  for (Eigen::Index j = 0; j < lattice.cols(); ++j) {
    const std::optional<kinematics::JointVector> q = joints_at(lattice.col(j));
    VRREG_THROW_UNLESS(q, "far-field cell: the " << testbed.name << " cannot reach lattice node "
                                                  << j);
    if (j == 0) label = kinematics::configuration_of(testbed.nominal, *q);
    plan.push_back({"F" + std::to_string(j), Role::kFiducial, lattice.col(j), std::nullopt, *q});
  }
  const double size_m = (o.nodes - 1) * o.spacing_m;
  Random direction_rng = Random::stream(o.seed, kDirectionStream);
  std::vector<double> distance_of;
  for (const double distance : o.distances) {
    for (int d = 0; d < o.directions; ++d) {
      const Eigen::Vector3d p =
          far_point_m(testbed.volume_centre_m, size_m, distance, unit_vector(direction_rng));
      const std::optional<kinematics::JointVector> q = joints_at(p);
      // Out of the arm's reach, or reached in another arm configuration than the fiducials (whose
      // errors are others: the joint model's case, not a field's): no target there.
      if (!q || kinematics::configuration_of(testbed.nominal, *q) != label) continue;
      plan.push_back({"T" + std::to_string(plan.size()), Role::kTarget, p, std::nullopt, *q});
      distance_of.push_back(distance);
    }
  }
  SimulationOptions options;
  options.seed = o.seed;
  TestbedErrorModel errors = testbed.default_errors;
  errors.tracker.readings_per_location = o.repeats;
  if (o.noise_sd_m > 0.0) errors.tracker.noise_sigma_m.setConstant(o.noise_sd_m);
  options.errors = errors;
  const SimulatedDataset data = simulate_plan(testbed, plan, options);
  const Points3 means = visit_means_m(data);
  FarFieldCell cell;
  cell.robot = testbed.name;
  const auto n_fid = lattice.cols();
  const auto n_tgt = static_cast<Eigen::Index>(distance_of.size());
  const Eigen::Index n_joints = testbed.nominal.n_joints();
  cell.fiducials_robot_m.resize(3, n_fid);
  cell.fiducials_sensor_m.resize(3, n_fid);
  cell.fiducials_q_rad.resize(n_joints, n_fid);
  cell.targets_robot_m.resize(3, n_tgt);
  cell.targets_sensor_m.resize(3, n_tgt);
  cell.targets_q_rad.resize(n_joints, n_tgt);
  for (std::size_t v = 0; v < data.visits.size(); ++v) {
    const auto i = static_cast<Eigen::Index>(v);
    const CommandedLocation& c = plan[v];
    if (i < n_fid) {
      cell.fiducials_robot_m.col(i) = c.robot_m;
      cell.fiducials_sensor_m.col(i) = means.col(i);
      cell.fiducials_q_rad.col(i) = c.q_rad;
    } else {
      cell.targets_robot_m.col(i - n_fid) = c.robot_m;
      cell.targets_sensor_m.col(i - n_fid) = means.col(i);
      cell.targets_q_rad.col(i - n_fid) = c.q_rad;
    }
  }
  cell.target_distance = distance_of;
  cell.noise_sd_m = errors.tracker.noise_sigma_m.norm() / std::sqrt(3.0 * o.repeats);
  return cell;
}

}  // namespace

const char* to_string(FarPhysics physics) {
  switch (physics) {
    case FarPhysics::kTrackerWarp: return "warp";
    case FarPhysics::kTrackerAxisWarp: return "axiswarp";
    case FarPhysics::kTrackerScale: return "scale";
    case FarPhysics::kTrackerAxisWarpAndScale: return "axis+scale";
    case FarPhysics::kUr5Robot: return "ur5";
    case FarPhysics::kLwr4Robot: return "lwr4";
  }
  return "?";
}

void FarFieldCellOptions::validate() const {
  VRREG_THROW_UNLESS(nodes >= 2 && nodes <= 40, "far-field cell: nodes " << nodes << " not in 2..40");
  VRREG_THROW_UNLESS(std::isfinite(spacing_m) && spacing_m > 0.0,
                     "far-field cell: spacing " << spacing_m << " m must be positive");
  VRREG_THROW_UNLESS(repeats >= 1, "far-field cell: repeats " << repeats << " must be >= 1");
  VRREG_THROW_UNLESS(std::isfinite(noise_sd_m) && noise_sd_m >= 0.0,
                     "far-field cell: noise " << noise_sd_m << " m must be >= 0");
  VRREG_THROW_UNLESS(directions >= 1, "far-field cell: directions must be >= 1");
  for (const double d : distances) {
    VRREG_THROW_UNLESS(std::isfinite(d) && d > 0.0, "far-field cell: distance " << d
                                                        << " lattice sizes must be positive");
  }
}

FarFieldCell far_field_cell(const FarFieldCellOptions& options) {
  options.validate();
  return options.physics == FarPhysics::kUr5Robot || options.physics == FarPhysics::kLwr4Robot
             ? robot_cell(options)
             : tracker_cell(options);
}

}  // namespace vrreg::simulation
