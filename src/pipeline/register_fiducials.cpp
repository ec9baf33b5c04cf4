// SPDX-License-Identifier: Apache-2.0
#include "vrreg/pipeline/register_fiducials.hpp"

#include <algorithm>

#include "model_corrector.hpp"
#include "orientation_rows.hpp"
#include "procedure2_steps.hpp"
#include "robust_rows.hpp"
#include "set_rows.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/correction/rrbc.hpp"

namespace vrreg {
namespace {

using pipeline_detail::fail;
using planning::Strategy;

// The registration weights of `rows`, or none when all are 1 (the paper's equal weights).
Eigen::VectorXd weights_of(const MeasurementSet& set, const std::vector<std::size_t>& rows) {
  const bool equal = std::all_of(rows.begin(), rows.end(),
                                 [&](std::size_t i) { return set.locations[i].weight == 1.0; });
  if (equal) return {};
  Eigen::VectorXd w(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t k = 0; k < rows.size(); ++k)
    w(static_cast<Eigen::Index>(k)) = set.locations[rows[k]].weight;
  return w;
}

// Registers the fiducial rows (of one configuration with options.config): no strategy, 1 or 2.
// Fills the model, the fit, the registered points and the robust report.
void register_rows(const MeasurementSet& set, const RegisterOptions& options, RegisterResult& out,
                   Points3& sensor, Points3& robot) {
  const std::vector<std::size_t> rows =
      pipeline_detail::select_rows(set, Role::kFiducial, options.config);
  RegistrationModel& model = out.model;
  model.source = set.source;
  model.config = options.config;
  model.interpolation = options.interpolation;

  std::vector<std::size_t> kept = rows;
  std::optional<pipeline_detail::RobustRows> robust;
  if (options.robust) {
    robust = pipeline_detail::robust_rows(set, rows, options);
    kept = robust->registered;
    for (const RejectedFiducial& r : robust->report.rejected) out.rejected.push_back(r.point);
  }
  sensor = set.sensor_points(kept);
  robot = set.robot_points(kept);
  out.registration = register_rigid(sensor, robot, options.registration, weights_of(set, kept));
  model.T_robot_sensor = out.registration.T_robot_sensor;
  model.fre_m = out.registration.fre_m;
  if (robust) {
    // Rejected fiducials keep their place with their neighbours' correction (a grid stays whole).
    pipeline_detail::fill_model_fiducials(set, rows, robust->report, model.T_robot_sensor, model);
    out.robust = std::move(robust->report);
    return;
  }
  model.fiducials = pipeline_detail::locations_of(set, kept);
  model.corrections_sensor_m = fiducial_corrections(model.T_robot_sensor, sensor, robot);  // Eq. 6
}

RegisterResult register_unchecked(const MeasurementSet& input, const RegisterOptions& options) {
  options.validate();
  const Strategy strategy = options.procedure2.strategy;
  RegisterResult out;
  const MeasurementSet* set = &input;
  MeasurementSet relabelled;
  if (strategy == Strategy::kAlongPath) {
    planning::Strategy2Result r =
        pipeline_detail::relabel(input, options.procedure2.joint_norm, options.robot);
    relabelled = std::move(r.set);
    out.relabelled = r.summary;
    set = &relabelled;
  }
  Points3 sensor, robot;
  if (strategy == Strategy::kVolumeCorners) {
    out.model = pipeline_detail::volume_corner_model(*set, options.procedure2, options.registration,
                                                     options.interpolation, out.registration,
                                                     sensor, robot);
  } else {
    register_rows(*set, options, out, sensor, robot);
    out.model.procedure2.strategy = strategy;
    out.model.procedure2.joint_norm = options.procedure2.joint_norm;
  }
  out.n_registered = static_cast<std::size_t>(sensor.cols());
  if (options.rigid_body_statistics) {
    const RigidBodyEstimate estimate =
        rigid_body_estimate(sensor, robot, options.sigma_l);  // Eq. 1
    out.rigid_body = estimate.statistics;
    out.sigma_l_sampling = estimate.sampling;
  }
  out.model.sigma_l_m = out.rigid_body.sigma_l_m;
  out.model.sigma_l_sampling = out.sigma_l_sampling;
  out.model.sigma_rep_m = options.sigma_rep_m;
  out.model.robot = options.robot;
  // As read (never relabelled): a check's file names them the same way.
  for (const std::size_t i : input.select(Role::kMonitor))
    out.model.monitors.push_back(input.locations[i]);
  out.noise = noise_figures(sigma_opt_m(out.model.fiducials), options.sigma_rep_m,
                            out.rigid_body.sigma_l_m);  // Eq. 9
  // The corrector evaluate and correct use, fitted once here (auto: by cross-validation) and
  // saved with the model. Not the default linear stencils: they are built when used (a grid
  // lookup or a Delaunay mesh, milliseconds at cell sizes), and registering 10^6 scanned
  // fiducials should not wait for a mesh nobody asked for.
  if (options.interpolation.method != InterpolationMethod::kLinear) {
    try {
      CorrectorOptions corrector_options = pipeline_detail::corrector_options(
          options.interpolation, strategy, options.procedure2.joint_norm);
      corrector_options.lost_motion = options.lost_motion;
      out.model.corrector = Corrector::fit(
          pipeline_detail::corrector_data(out.model, out.model.robot), corrector_options);
      if (out.model.has_fiducial_orientations()) {  // rigid-body markers
        out.model.orientation_corrector =
            pipeline_detail::fit_orientation(out.model, *out.model.corrector, out.model.robot);
      }
    } catch (const FileError&) {
      throw;
    } catch (const InputError& e) {
      fail(*set, e.what());
    }
  }
  if (options.interpolation.method == InterpolationMethod::kAuto) {
    // The model stores what cross-validation chose, so evaluate and correct need not choose again.
    out.cross_validation = out.model.corrector->cross_validation();
    out.model.interpolation.method = out.model.corrector->method();
  }
  return out;
}

}  // namespace

void RegisterOptions::validate() const {
  registration.validate();
  interpolation.validate();
  if (robust) robust->validate();
  sigma_l.validate();
  VRREG_THROW_UNLESS(lost_motion != LostMotionMode::kOn ||
                         interpolation.method != InterpolationMethod::kLinear,
                     "lost motion is fitted with the corrector: choose `interpolation` auto or a "
                     "field model, not linear");
  VRREG_THROW_UNLESS(
      !sigma_rep_m || (std::isfinite(*sigma_rep_m) && *sigma_rep_m >= 0.0),
      "the robot repeatability must be finite and >= 0, got " << *sigma_rep_m << " m");
  const Strategy s = procedure2.strategy;
  const int n = planning::strategy_number(s);
  VRREG_THROW_UNLESS((s != Strategy::kAsListed && s != Strategy::kAlongPath) || config,
                     "`strategy` " << n << " registers one configuration: give `config`");
  VRREG_THROW_UNLESS(s != Strategy::kVolumeCorners || !config,
                     "`strategy` 3 registers every configuration at once; "
                     "`config` selects targets in evaluate");
  VRREG_THROW_UNLESS(s != Strategy::kVolumeCorners || !robust,
                     "`robust` is not available with `strategy` 3");
  VRREG_THROW_UNLESS(s != Strategy::kVolumeCorners ||
                         interpolation.method == InterpolationMethod::kLinear ||
                         interpolation.method == InterpolationMethod::kOctuplet,
                     "`strategy` 3 corrects with octuplets (`cube_edge`), not `interpolation` "
                         << to_string(interpolation.method));
  VRREG_THROW_UNLESS(s != Strategy::kAlongPath || !is_field_model(interpolation.method),
                     "`strategy` 2 corrects with the paper's stencils, not `interpolation` "
                         << to_string(interpolation.method));
  VRREG_THROW_UNLESS(s == Strategy::kVolumeCorners || !procedure2.seed,
                     "`seed` is for `strategy` 3");
  VRREG_THROW_UNLESS(procedure2.registration_fiducials.empty(),
                     "registration_fiducials are chosen by Strategy 3, not given");
}

RegisterResult register_fiducials(const MeasurementSet& fiducials, const RegisterOptions& options) {
  return register_unchecked(fiducials, options);
}

RegisterResult register_fiducials(const MeasuredPoints& fiducials, const RegisterOptions& options) {
  return register_unchecked(fiducials.to_measurement_set(Role::kFiducial, true), options);
}

RegisterResult register_fiducials(const ConstPoints3Ref& sensor_m, const ConstPoints3Ref& robot_m,
                                  const RegisterOptions& options) {
  MeasuredPoints fiducials;
  fiducials.sensor_m = sensor_m;
  fiducials.robot_m = robot_m;
  return register_fiducials(fiducials, options);
}

}  // namespace vrreg
