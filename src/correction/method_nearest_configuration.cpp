// SPDX-License-Identifier: Apache-2.0
// Strategy 3 of Procedure 2 (paper section 4.4), correction half, as a correction method: the
// octuplet of Eq. 7 (weights 1/8) whose every corner is the fiducial, among those measured at
// that corner in each arm configuration, whose joints are nearest the target's.
#include <algorithm>
#include <sstream>

#include "method_support.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/correction/corner_candidates.hpp"

namespace vrreg::detail {
namespace {

class NearestConfigurationMethod final : public FittedMethod {
 public:
  NearestConfigurationMethod(const CorrectorData& data, const MethodSettings& settings)
      : candidates_(data.fiducials_robot_m, settings.match_tolerance_m),
        joints_rad_(data.joints_rad),
        corrections_sensor_m_(data.corrections_sensor_m),
        cube_edge_m_(settings.cube_edge_m),
        norm_(*settings.nearest_configuration),
        kinds_(data.robot ? kinematics::JointKinds(*data.robot) : kinematics::JointKinds()) {}

  [[nodiscard]] InterpolationMethod method() const override {
    return InterpolationMethod::kOctuplet;
  }
  [[nodiscard]] std::string describe() const override {
    std::ostringstream layout;
    layout << "octuplet, cube edge " << units::m_to_mm(cube_edge_m_)
           << " mm, each corner in the configuration nearest the target's ("
           << kinematics::to_string(norm_) << ")";
    return layout.str();
  }
  [[nodiscard]] MethodNeeds needs() const override {
    return {.nominal_robot = true, .joints = true};
  }

  void check_query(const MethodQuery& query) const override {
    VRREG_THROW_UNLESS(query.joints_rad.rows() == joints_rad_.rows(),
                       "Strategy 3: the fiducials have " << joints_rad_.rows()
                                                         << " joints, the targets "
                                                         << query.joints_rad.rows());
  }

  void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
               MethodPredictions& out) const override {
    for (Eigen::Index i = begin; i < end; ++i) {
      Stencil& s = out.stencils[static_cast<std::size_t>(i)];
      s = stencil(query.robot_nominal_m.col(i), query.joints_rad.col(i));
      if (s.status == StencilStatus::kOk) {
        out.corrections_sensor_m.col(i) = interpolate_correction(s, corrections_sensor_m_);
      } else {
        out.corrections_sensor_m.col(i).setZero();
      }
    }
  }

  [[nodiscard]] MethodState save() const override { return MethodState("octuplet"); }

 private:
  // The 8 corners, each the candidate whose joints are nearest the target's (ties: the first).
  [[nodiscard]] Stencil stencil(const Eigen::Vector3d& target_robot_m,
                                const Eigen::Ref<const Eigen::VectorXd>& target_q_rad) const {
    const CornerFiducials corners = candidates_.octuplet(target_robot_m, cube_edge_m_);
    if (std::any_of(corners.begin(), corners.end(), [](const auto& c) { return c.empty(); })) {
      return flagged_stencil(StencilStatus::kMissingCorner);
    }
    Stencil s;
    for (std::size_t c = 0; c < 8; ++c) {
      const std::vector<Eigen::Index>& candidates = corners[c];
      Eigen::MatrixXd q(joints_rad_.rows(), static_cast<Eigen::Index>(candidates.size()));
      for (std::size_t k = 0; k < candidates.size(); ++k)
        q.col(static_cast<Eigen::Index>(k)) = joints_rad_.col(candidates[k]);
      s.fiducial[c] = candidates[static_cast<std::size_t>(
          *kinematics::nearest_configuration(q, target_q_rad, norm_, kinds_))];
      s.weight[c] = 0.125;
    }
    s.size = 8;
    return s;
  }

  CornerCandidates candidates_;
  Eigen::MatrixXd joints_rad_;
  Points3 corrections_sensor_m_;
  double cube_edge_m_;
  kinematics::JointNorm norm_;
  kinematics::JointKinds kinds_;  // a slide's travel [m] is not an angle
};

void check_nearest_configuration(const CorrectorData& data, const MethodSettings& settings) {
  VRREG_THROW_UNLESS(
      std::isfinite(settings.match_tolerance_m) && settings.match_tolerance_m > 0.0,
      "Strategy 3: the match tolerance must be > 0, got " << settings.match_tolerance_m << " m");
  VRREG_THROW_UNLESS(std::isfinite(settings.cube_edge_m) &&
                         settings.cube_edge_m > 4.0 * settings.match_tolerance_m,
                     "Strategy 3 corrects with octuplets and needs a cube edge (got "
                         << units::m_to_mm(settings.cube_edge_m) << " mm): set `cube_edge`");
  VRREG_THROW_UNLESS(data.has_joints(),
                     "Strategy 3 needs the fiducials' joints (q1_rad..qN_rad)");
}

}  // namespace

FitOutcome fit_nearest_configuration(const CorrectorData& data, const MethodSettings& settings) {
  check_nearest_configuration(data, settings);
  return fitted<NearestConfigurationMethod>(data, settings);
}

std::unique_ptr<const FittedMethod> restore_nearest_configuration(const CorrectorData& data,
                                                                  const MethodSettings& settings) {
  check_nearest_configuration(data, settings);
  return std::make_unique<const NearestConfigurationMethod>(data, settings);
}

}  // namespace vrreg::detail
