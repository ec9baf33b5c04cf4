// SPDX-License-Identifier: Apache-2.0
#include "vrreg/pipeline/plan_next_correction.hpp"

#include <string>
#include <utility>

#include "vrreg/core/check.hpp"
#include "vrreg/pipeline/correct.hpp"

namespace vrreg {

planning::CorrectionSdAtParts correction_sd_at_parts(MeasurementSet measured,
                                                     RegisterOptions options) {
  // What no number of fiducials mends is bad input, not "no sd yet": a joint-space model
  // without the arm, or without the joints in the file, or with another count of them.
  if (options.interpolation.method == InterpolationMethod::kJoint) {
    VRREG_THROW_UNLESS(options.robot, "joint interpolation needs the robot");
    VRREG_THROW_UNLESS(measured.n_joints == options.robot->n_joints(),
                       "joint interpolation needs the fiducials' joint angles, "
                           << options.robot->n_joints() << " per row for " << options.robot->name()
                           << "; the measurements have " << measured.n_joints);
  }
  return [measured = std::move(measured), options = std::move(options)](
             const std::vector<planning::PartPlan>& parts) {
    planning::CorrectionSd out;
    out.method = to_string(options.interpolation.method);
    RegisterResult reg;
    try {
      reg = register_fiducials(measured, options);
    } catch (const InputError& e) {
      out.note = e.what();  // e.g. too few fiducials for the method yet
      return out;
    }
    MeasuredPoints points;
    const auto n = static_cast<Eigen::Index>(parts.size());
    Points3 robot_m(3, n);
    Eigen::MatrixXd q_rad;
    for (Eigen::Index i = 0; i < n; ++i) {
      const planning::PartPlan& p = parts[static_cast<std::size_t>(i)];
      robot_m.col(i) = p.robot_m;
      if (q_rad.size() == 0) q_rad.resize(p.q_rad.size(), n);
      q_rad.col(i) = p.q_rad;
      points.names.push_back(p.name);
    }
    // Where the sensor sees a part point: the registration's inverse of its nominal position.
    points.sensor_m = reg.model.T_robot_sensor.inverse().apply_all(robot_m);
    points.robot_m = robot_m;
    points.joints_rad = q_rad;
    const CorrectResult corrected = correct(reg.model, points);
    out.method = to_string(corrected.interpolation.method);
    if (corrected.correction.n_flagged > 0) {
      out.note = std::to_string(corrected.correction.n_flagged) + " of " + std::to_string(n) +
                 " part points are outside the model's support";
      return out;
    }
    const Eigen::VectorXd& sd_m = corrected.correction.predicted_sd_m;
    if (sd_m.size() != n || !sd_m.allFinite()) {
      out.note = "the model predicts no sd at every part point";
      return out;
    }
    out.sd_m = sd_m;
    return out;
  };
}

}  // namespace vrreg
