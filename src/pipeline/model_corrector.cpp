// SPDX-License-Identifier: Apache-2.0
#include "model_corrector.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "vrreg/metrics/noise.hpp"

namespace vrreg::pipeline_detail {
namespace {

// Whether `c` was fitted for `options` (the same settings; `auto` or `linear` also answer a
// request for the method they chose).
bool answers(const Corrector& c, const CorrectorOptions& options) {
  const InterpolationSettings& asked = options.interpolation;
  const InterpolationSettings& fitted = c.requested();
  const bool method = asked.method == fitted.method || asked.method == c.method();
  const bool octuplet = asked.method == InterpolationMethod::kOctuplet;
  return method && asked.match_tolerance_m == fitted.match_tolerance_m &&
         (!octuplet || asked.cube_edge_m == fitted.cube_edge_m) &&
         options.nearest_configuration == c.nearest_configuration();
}

}  // namespace

CorrectorData corrector_data(const RegistrationModel& model,
                             const std::optional<kinematics::SerialChain>& robot) {
  const CorrectionField field = model.correction_field();
  CorrectorData data;
  data.T_robot_sensor = model.T_robot_sensor;
  data.fiducials_robot_m = field.fiducials_robot_m;
  data.corrections_sensor_m = field.corrections_sensor_m;
  data.sequence = field.fiducials_sequence;
  const auto n = static_cast<Eigen::Index>(model.fiducials.size());
  data.registered_robot_m.resize(3, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    data.registered_robot_m.col(j) =
        model.T_robot_sensor.apply(model.fiducials[static_cast<std::size_t>(j)].sensor_m);
  }
  const std::size_t n_joints = model.fiducials.empty() ? 0 : model.fiducials.front().q_rad.size();
  bool joints = n_joints > 0;
  for (const Location& f : model.fiducials) joints = joints && f.q_rad.size() == n_joints;
  if (joints) {
    data.joints_rad.resize(static_cast<Eigen::Index>(n_joints), n);
    for (Eigen::Index j = 0; j < n; ++j) {
      const std::vector<double>& q = model.fiducials[static_cast<std::size_t>(j)].q_rad;
      data.joints_rad.col(j) = Eigen::Map<const Eigen::VectorXd>(q.data(), q.size());
    }
  }
  // The approach directions, when every fiducial has them (the lost-motion term's input).
  bool approach = joints;
  for (const Location& f : model.fiducials)
    approach = approach && f.approach_sign.size() == n_joints;
  if (approach) {
    data.approach_sign.resize(static_cast<Eigen::Index>(n_joints), n);
    for (Eigen::Index j = 0; j < n; ++j) {
      const std::vector<double>& s = model.fiducials[static_cast<std::size_t>(j)].approach_sign;
      data.approach_sign.col(j) = Eigen::Map<const Eigen::VectorXd>(s.data(), s.size());
    }
  }
  for (const Location& f : model.fiducials) data.configs.push_back(f.config);
  data.robot = robot;
  // The measured part of one fiducial's noise per axis: its averaged sensor reading, sigma_opt
  // per reading over sqrt n. The robot's repeatability is left to the fit (kriging's nugget
  // excess): a datasheet's sigma_rep is a bound, often 2-3 sigma, and as a floor it over-smooths
  // (simulated A1: 0.141 mm and sd 1.3x too wide with the 0.1 mm spec; 0.127 mm, calibrated,
  // without it).
  const std::optional<double> opt = sigma_opt_m(model.fiducials);
  if (opt)
    data.noise_sd_m = *opt / std::sqrt(static_cast<double>(median_readings(model.fiducials)));
  return data;
}

CorrectorOptions corrector_options(const InterpolationSettings& settings,
                                   planning::Strategy strategy, kinematics::JointNorm norm) {
  CorrectorOptions options;
  options.interpolation = settings;
  if (strategy == planning::Strategy::kVolumeCorners) {
    options.interpolation.method = InterpolationMethod::kOctuplet;
    options.nearest_configuration = norm;
  }
  return options;
}

namespace {

// The same arm as the model's: the same geometry, limits, base and tool, to the bit (the robot
// a model was registered with, named again on the command line).
bool same_robot(const kinematics::SerialChain& a, const kinematics::SerialChain& b) {
  if (a.n_rows() != b.n_rows() || a.couplings() != b.couplings()) return false;
  for (int i = 0; i < a.n_rows(); ++i) {
    const kinematics::DhRow& r = a.row(i);
    const kinematics::DhRow& s = b.row(i);
    if (r.a_m != s.a_m || r.alpha_rad != s.alpha_rad || r.d_m != s.d_m ||
        r.theta_offset_rad != s.theta_offset_rad || r.type != s.type ||
        a.limits()[static_cast<std::size_t>(i)] != b.limits()[static_cast<std::size_t>(i)]) {
      return false;
    }
  }
  return a.T_base_dh0().matrix() == b.T_base_dh0().matrix() &&
         a.T_flange_tcp().matrix() == b.T_flange_tcp().matrix();
}

}  // namespace

Corrector corrector_for(const RegistrationModel& model, const CorrectorRequest& request) {
  const CorrectorOptions options =
      corrector_options(request.settings, request.strategy, request.norm);
  // A robot given now refits what depends on it: the joint-space model, and auto's choice.
  const bool robot_changes =
      request.robot && !(model.robot && same_robot(*request.robot, *model.robot)) &&
      (request.settings.method == InterpolationMethod::kJoint ||
       request.settings.method == InterpolationMethod::kAuto);
  const auto data = [&] { return corrector_data(model, request.robot ? request.robot : model.robot); };
  if (model.corrector && !request.refit && !robot_changes && answers(*model.corrector, options)) {
    return request.exact ? model.corrector->exact(data()) : *model.corrector;
  }
  CorrectorOptions fitted = options;
  fitted.tabulate = !request.exact;
  return Corrector::fit(data(), fitted);
}

}  // namespace vrreg::pipeline_detail

namespace vrreg {

Corrector restore_corrector(const RegistrationModel& model, const SavedCorrector& saved) {
  return Corrector::restore(saved, pipeline_detail::corrector_data(model, model.robot));
}

}  // namespace vrreg
