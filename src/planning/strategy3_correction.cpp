// SPDX-License-Identifier: Apache-2.0
// Strategy 3's correction through the nearest-configuration correction method
// (correction/corrector.hpp), on fiducials and targets given as locations.
#include "vrreg/planning/strategy3_correction.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/correction/corrector.hpp"

namespace vrreg::planning {
namespace {

// Joint angles of `locations`, one column each; every location must have `n` of them.
Eigen::MatrixXd joints_of(const std::vector<Location>& locations, std::size_t n, const char* what) {
  Eigen::MatrixXd q(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(locations.size()));
  for (std::size_t k = 0; k < locations.size(); ++k) {
    const Location& loc = locations[k];
    VRREG_THROW_UNLESS(!loc.q_rad.empty(),
                       "Strategy 3: " << what << " '" << loc.point << "' has no joints (q1_rad..qN_rad)");
    VRREG_THROW_UNLESS(loc.q_rad.size() == n, "Strategy 3: " << what << " '" << loc.point
                                                              << "' has " << loc.q_rad.size()
                                                              << " joints, expected " << n);
    q.col(static_cast<Eigen::Index>(k)) =
        Eigen::Map<const Eigen::VectorXd>(loc.q_rad.data(), static_cast<Eigen::Index>(n));
  }
  return q;
}

Corrector strategy3_corrector(const SimilarityTransform& T_robot_sensor,
                              const std::vector<Location>& fiducials,
                              const ConstPoints3Ref& corrections_sensor_m,
                              const Strategy3CorrectionOptions& options) {
  options.validate();
  VRREG_THROW_UNLESS(!fiducials.empty(), "the model has no fiducials to correct with");
  VRREG_THROW_UNLESS(
      corrections_sensor_m.cols() == static_cast<Eigen::Index>(fiducials.size()),
      "the model has " << corrections_sensor_m.cols() << " fiducial corrections for "
                       << fiducials.size() << " fiducials");
  CorrectorData data;
  data.T_robot_sensor = T_robot_sensor;
  data.fiducials_robot_m.resize(3, static_cast<Eigen::Index>(fiducials.size()));
  for (std::size_t j = 0; j < fiducials.size(); ++j)
    data.fiducials_robot_m.col(static_cast<Eigen::Index>(j)) = fiducials[j].robot_m;
  data.corrections_sensor_m = corrections_sensor_m;
  // Eq. 6 backwards: R X_j + tau = Y_j - s R epsilon_j.
  data.registered_robot_m =
      data.fiducials_robot_m - T_robot_sensor.scale * (T_robot_sensor.rotation * corrections_sensor_m);
  data.joints_rad = joints_of(fiducials, fiducials.front().q_rad.size(), "fiducial");
  CorrectorOptions corrector;
  corrector.interpolation.method = InterpolationMethod::kOctuplet;
  corrector.interpolation.cube_edge_m = options.cube_edge_m;
  corrector.interpolation.match_tolerance_m = options.match_tolerance_m;
  corrector.nearest_configuration = options.norm;
  return Corrector::fit(data, corrector);
}

TargetCorrection correct(const Corrector& corrector, const std::vector<Location>& targets,
                         std::size_t n_joints) {
  Points3 sensor(3, static_cast<Eigen::Index>(targets.size()));
  Points3 robot(3, sensor.cols());
  for (std::size_t t = 0; t < targets.size(); ++t) {
    sensor.col(static_cast<Eigen::Index>(t)) = targets[t].sensor_m;
    robot.col(static_cast<Eigen::Index>(t)) = targets[t].robot_m;
  }
  return corrector.correct(
      CorrectionQuery(sensor, robot, joints_of(targets, n_joints, "target")));
}

}  // namespace

void Strategy3CorrectionOptions::validate() const {
  VRREG_THROW_UNLESS(
      std::isfinite(match_tolerance_m) && match_tolerance_m > 0.0,
      "Strategy 3: the match tolerance must be > 0, got " << match_tolerance_m << " m");
  VRREG_THROW_UNLESS(std::isfinite(cube_edge_m) && cube_edge_m > 4.0 * match_tolerance_m,
                     "Strategy 3 corrects with octuplets and needs a cube edge (got "
                         << units::m_to_mm(cube_edge_m) << " mm): set `cube_edge`");
}

std::vector<Stencil> nearest_configuration_stencils(const std::vector<Location>& fiducials,
                                                    const std::vector<Location>& targets,
                                                    const Strategy3CorrectionOptions& options) {
  const Points3 none = Points3::Zero(3, static_cast<Eigen::Index>(fiducials.size()));
  const Corrector c = strategy3_corrector(SimilarityTransform(), fiducials, none, options);
  return correct(c, targets, fiducials.front().q_rad.size()).stencils;
}

TargetCorrection correct_targets_strategy3(const SimilarityTransform& T_robot_sensor,
                                           const std::vector<Location>& fiducials,
                                           const ConstPoints3Ref& corrections_sensor_m,
                                           const std::vector<Location>& targets,
                                           const Strategy3CorrectionOptions& options) {
  const Corrector c = strategy3_corrector(T_robot_sensor, fiducials, corrections_sensor_m, options);
  return correct(c, targets, fiducials.front().q_rad.size());
}

}  // namespace vrreg::planning
