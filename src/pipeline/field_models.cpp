// Dispatch over the field models and what each needs (docs/field-models.md).
#include "field_models.hpp"

#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include "vrreg/core/check.hpp"

namespace vrreg::pipeline_detail {
namespace {

/// Joint angles further apart than this at one nominal position are another arm configuration.
constexpr double kSameConfigurationRad = 1e-3;

/// Two fiducials at one nominal position (the same after rounding to data.tolerance_m, as
/// repeated nominal positions in a file are) in different arm configurations, which a field of
/// position alone cannot tell apart; empty when none.
std::string configuration_clash(const FieldData& data) {
  if (data.joints_rad.size() == 0) return {};
  std::map<std::array<long long, 3>, Eigen::Index> first_at;
  for (Eigen::Index j = 0; j < data.size(); ++j) {
    std::array<long long, 3> key{};
    for (int axis = 0; axis < 3; ++axis)
      key[static_cast<std::size_t>(axis)] =
          std::llround(data.fiducials_robot_m(axis, j) / data.tolerance_m);
    const auto [it, inserted] = first_at.emplace(key, j);
    if (inserted) continue;
    const Eigen::Index k = it->second;
    if ((data.joints_rad.col(j) - data.joints_rad.col(k)).cwiseAbs().maxCoeff() >
        kSameConfigurationRad) {
      std::ostringstream out;
      out << "fiducials " << k << " and " << j
          << " share a nominal robot position in different arm configurations (use joint, or "
             "one model per configuration)";
      return out.str();
    }
  }
  return {};
}

}  // namespace

FieldData FieldData::subset(const std::vector<Eigen::Index>& keep) const {
  FieldData out;
  out.T_robot_sensor = T_robot_sensor;
  out.robot = robot;
  out.noise_sd_m = noise_sd_m;
  out.tolerance_m = tolerance_m;
  const auto n = static_cast<Eigen::Index>(keep.size());
  out.fiducials_robot_m.resize(3, n);
  out.registered_robot_m.resize(3, n);
  out.corrections_sensor_m.resize(3, n);
  if (joints_rad.size() > 0) out.joints_rad.resize(joints_rad.rows(), n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index j = keep[static_cast<std::size_t>(i)];
    out.fiducials_robot_m.col(i) = fiducials_robot_m.col(j);
    out.registered_robot_m.col(i) = registered_robot_m.col(j);
    out.corrections_sensor_m.col(i) = corrections_sensor_m.col(j);
    if (joints_rad.size() > 0) out.joints_rad.col(i) = joints_rad.col(j);
  }
  return out;
}

std::unique_ptr<FieldModel> FieldModel::refit(const FieldData& subset) const {
  return fit_field_model(method(), subset);
}

std::string field_model_unavailable(InterpolationMethod method, const FieldData& data) {
  if (method == InterpolationMethod::kJoint) {
    if (data.joints_rad.size() == 0) return "the fiducials have no joint angles";
    if (!data.robot) return "no robot given (--robot)";
    if (data.joints_rad.rows() != data.robot->n_joints())
      return "the fiducials have " + std::to_string(data.joints_rad.rows()) +
             " joint angles, the robot " + std::to_string(data.robot->n_joints());
  }
  if (data.size() < 12) return "fewer than 12 fiducials";
  // The other position-only models refuse any shared position when they are built; kriging
  // takes repeated readings of one configuration (its nugget), not another configuration.
  if (method == InterpolationMethod::kKriging) return configuration_clash(data);
  return {};
}

std::unique_ptr<FieldModel> fit_field_model(InterpolationMethod method, const FieldData& data) {
  const std::string why = field_model_unavailable(method, data);
  VRREG_THROW_UNLESS(why.empty(), to_string(method) << " interpolation cannot be used: " << why);
  switch (method) {
    case InterpolationMethod::kScattered: return fit_scattered_model(data);
    case InterpolationMethod::kTrilinear: return fit_trilinear_model(data);
    case InterpolationMethod::kKriging: return fit_kriging_model(data);
    case InterpolationMethod::kRbf: return fit_rbf_model(data);
    case InterpolationMethod::kJoint: return fit_joint_model(data);
    default: break;
  }
  VRREG_THROW_UNLESS(false, to_string(method) << " is not a field model");
}

}  // namespace vrreg::pipeline_detail
