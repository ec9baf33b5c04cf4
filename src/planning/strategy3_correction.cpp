// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/strategy3_correction.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/correction/corner_candidates.hpp"

namespace vrreg::planning {
namespace {

Eigen::Map<const Eigen::VectorXd> joints_of(const Location& loc) {
  return {loc.q_rad.data(), static_cast<Eigen::Index>(loc.q_rad.size())};
}

// The candidate whose joints are nearest the target's (ties: the first).
Eigen::Index nearest_candidate(const std::vector<Location>& fiducials,
                               const std::vector<Eigen::Index>& candidates, const Location& target,
                               kinematics::JointNorm norm) {
  Eigen::MatrixXd q(static_cast<Eigen::Index>(target.q_rad.size()),
                    static_cast<Eigen::Index>(candidates.size()));
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const Location& f = fiducials[static_cast<std::size_t>(candidates[k])];
    VRREG_THROW_UNLESS(f.q_rad.size() == target.q_rad.size(),
                       "Strategy 3: fiducial '" << f.point << "' has " << f.q_rad.size()
                                                << " joints, target '" << target.point << "' "
                                                << target.q_rad.size());
    q.col(static_cast<Eigen::Index>(k)) = joints_of(f);
  }
  return candidates[static_cast<std::size_t>(
      *kinematics::nearest_configuration(q, joints_of(target), norm))];
}

}  // namespace

void Strategy3CorrectionOptions::validate() const {
  VRREG_THROW_UNLESS(
      std::isfinite(match_tolerance_m) && match_tolerance_m > 0.0,
      "Strategy 3: the match tolerance must be > 0, got " << match_tolerance_m << " m");
  VRREG_THROW_UNLESS(std::isfinite(cube_edge_m) && cube_edge_m > 4.0 * match_tolerance_m,
                     "Strategy 3 corrects with octuplets and needs a cube edge (got "
                         << units::m_to_mm(cube_edge_m) << " mm): set --cube-mm");
}

std::vector<Stencil> nearest_configuration_stencils(const std::vector<Location>& fiducials,
                                                    const std::vector<Location>& targets,
                                                    const Strategy3CorrectionOptions& options) {
  options.validate();
  Points3 robot(3, static_cast<Eigen::Index>(fiducials.size()));
  for (std::size_t j = 0; j < fiducials.size(); ++j) {
    robot.col(static_cast<Eigen::Index>(j)) = fiducials[j].robot_m;
  }
  const CornerCandidates candidates(robot, options.match_tolerance_m);
  std::vector<Stencil> out(targets.size());
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const Location& target = targets[t];
    VRREG_THROW_UNLESS(!target.q_rad.empty(), "Strategy 3: target '"
                                                  << target.point
                                                  << "' has no joints (q1_rad..qN_rad)");
    const CornerFiducials corners = candidates.octuplet(target.robot_m, options.cube_edge_m);
    Stencil& s = out[t];
    const bool complete =
        std::none_of(corners.begin(), corners.end(), [](const auto& c) { return c.empty(); });
    if (!complete) {
      s.status = StencilStatus::kMissingCorner;
      continue;
    }
    for (std::size_t c = 0; c < 8; ++c) {
      s.fiducial[c] = nearest_candidate(fiducials, corners[c], target, options.norm);
      s.weight[c] = 0.125;
    }
    s.size = 8;
  }
  return out;
}

TargetCorrection correct_targets_strategy3(const SimilarityTransform& T_robot_sensor,
                                           const std::vector<Location>& fiducials,
                                           const ConstPoints3Ref& corrections_sensor_m,
                                           const std::vector<Location>& targets,
                                           const Strategy3CorrectionOptions& options) {
  VRREG_THROW_UNLESS(!fiducials.empty(), "the model has no fiducials to correct with");
  VRREG_THROW_UNLESS(
      corrections_sensor_m.cols() == static_cast<Eigen::Index>(fiducials.size()),
      "the model has " << corrections_sensor_m.cols() << " fiducial corrections for "
                       << fiducials.size() << " fiducials");
  TargetCorrection out;
  out.method_used = InterpolationMethod::kOctuplet;
  std::ostringstream layout;
  layout << "octuplet, cube edge " << units::m_to_mm(options.cube_edge_m)
         << " mm, each corner in the configuration nearest the target's ("
         << kinematics::to_string(options.norm) << ")";
  out.layout = layout.str();
  out.stencils = nearest_configuration_stencils(fiducials, targets, options);
  const auto n = static_cast<Eigen::Index>(targets.size());
  out.corrections_sensor_m = Points3::Zero(3, n);
  out.corrected_sensor_m.resize(3, n);
  out.corrected_robot_m.resize(3, n);
  out.uncorrected_robot_m.resize(3, n);
  const SimilarityTransform& T = T_robot_sensor;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Location& target = targets[static_cast<std::size_t>(i)];
    const Stencil& s = out.stencils[static_cast<std::size_t>(i)];
    if (s.status == StencilStatus::kOk) {
      out.corrections_sensor_m.col(i) = interpolate_correction(s, corrections_sensor_m);
    } else {
      ++out.n_flagged;
    }
    out.corrected_sensor_m.col(i) = target.sensor_m + out.corrections_sensor_m.col(i);
    out.uncorrected_robot_m.col(i) = T.apply(target.sensor_m);
    out.corrected_robot_m.col(i) = T.apply(out.corrected_sensor_m.col(i));
  }
  return out;
}

}  // namespace vrreg::planning
