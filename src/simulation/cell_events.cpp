// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/cell_events.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "vrreg/core/check.hpp"

namespace vrreg::simulation {

double ThermalModel::growth_at(double t_s) const {
  const double warm = warmup_growth * -std::expm1(-std::max(t_s, 0.0) / warmup_time_constant_s);
  return warm + daily_growth * std::sin(2.0 * std::numbers::pi * t_s / daily_period_s);
}

void ThermalModel::validate() const {
  VRREG_THROW_UNLESS(std::isfinite(warmup_growth) && std::isfinite(daily_growth) &&
                         std::abs(warmup_growth) + std::abs(daily_growth) < 0.01,
                     "thermal model: growths must be finite and sum below 0.01 in size");
  VRREG_THROW_UNLESS(std::isfinite(warmup_time_constant_s) && warmup_time_constant_s > 0.0 &&
                         std::isfinite(daily_period_s) && daily_period_s > 0.0,
                     "thermal model: the time constant and period must be > 0");
}

void CellEvents::validate() const {
  thermal.validate();
  VRREG_THROW_UNLESS(!std::isnan(bump_time_s), "cell events: the bump time is not a number");
  VRREG_THROW_UNLESS(std::isfinite(bump_rms_m) && bump_rms_m >= 0.0,
                     "cell events: the bump size must be finite and >= 0");
}

RigidTransform testbed_bump(const Testbed& testbed, const RigidTransform& T_robot_sensor,
                            double rms_m, std::uint64_t seed) {
  constexpr std::uint64_t kBumpStream = 300;
  Points3 corners(3, 8);
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d offset((c & 1) ? 0.15 : -0.15, (c & 2) ? 0.15 : -0.15,
                                 (c & 4) ? 0.15 : -0.15);
    corners.col(c) = T_robot_sensor.inverse().apply(testbed.volume_centre_m + offset);
  }
  Random rng = Random::stream(seed, kBumpStream);
  return draw_bump(corners, rms_m, rng);
}

RigidTransform draw_bump(const ConstPoints3Ref& cell_sensor_m, double rms_m, Random& rng) {
  VRREG_THROW_UNLESS(cell_sensor_m.cols() >= 1 && cell_sensor_m.allFinite(),
                     "bump: needs finite cell points");
  VRREG_THROW_UNLESS(std::isfinite(rms_m) && rms_m >= 0.0, "bump: the size must be >= 0");
  const Eigen::Vector3d centre = cell_sensor_m.rowwise().mean();
  Eigen::Vector3d axis = rng.normal3(1.0);
  while (axis.norm() < 1e-6) axis = rng.normal3(1.0);
  const Eigen::Vector3d pivot = centre + rng.normal3(0.5);  // a tripod's head, a mount's screw
  const Eigen::Vector3d shift = rng.normal3(1.0);
  // A unit-size motion, then scaled (small motions: the displacement is linear in the size).
  const auto motion = [&](double s) {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(s * 1e-4, axis.normalized()).toRotationMatrix();
    return RigidTransform(R, pivot - R * pivot + s * 1e-5 * shift);
  };
  const auto rms_of = [&](const RigidTransform& T) {
    return std::sqrt((T.apply_all(cell_sensor_m) - cell_sensor_m).colwise().squaredNorm().mean());
  };
  const double unit = rms_of(motion(1.0));
  VRREG_THROW_UNLESS(unit > 0.0, "bump: the drawn motion does not move the cell");
  double s = rms_m / unit;
  for (int i = 0; i < 3; ++i) s *= rms_m / std::max(rms_of(motion(s)), 1e-300);  // exact size
  return rms_m == 0.0 ? RigidTransform() : motion(s);
}

SimulatedRobot grown(const SimulatedRobot& robot, double growth) {
  RobotErrorModel model = robot.model();
  model.link_growth = growth;
  return SimulatedRobot(robot.nominal(), model, robot.errors());
}

double growth_for_displacement(const SimulatedRobot& robot, const Eigen::MatrixXd& q_rad,
                               double rms_m) {
  VRREG_THROW_UNLESS(q_rad.cols() >= 1 && std::isfinite(rms_m) && rms_m >= 0.0,
                     "growth for displacement: needs poses and a size >= 0");
  constexpr double kTrial = 1e-4;
  const SimulatedRobot trial = grown(robot, robot.model().link_growth + kTrial);
  double ss = 0.0;
  for (Eigen::Index k = 0; k < q_rad.cols(); ++k) {
    const kinematics::JointVector q = q_rad.col(k);
    ss += (trial.actual_tcp_m(q) - robot.actual_tcp_m(q)).squaredNorm();
  }
  const double per_trial = std::sqrt(ss / static_cast<double>(q_rad.cols()));
  VRREG_THROW_UNLESS(per_trial > 0.0, "growth for displacement: growth does not move the TCP");
  return robot.model().link_growth + kTrial * rms_m / per_trial;
}

}  // namespace vrreg::simulation
