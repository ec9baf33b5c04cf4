// SPDX-License-Identifier: Apache-2.0
// Beyond the paper: every correction method on one registration of a dataset's fiducials, the
// results cut into tables per group of targets (the KUKA's configurations).
#include <cmath>
#include <exception>

#include "vrreg/core/check.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/experiments/beyond_paper.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/metrics/uncertainty_calibration.hpp"
#include "vrreg/pipeline/evaluate.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"

namespace vrreg::experiments {
namespace {

// One evaluation of all targets, or why there is none.
struct Outcome {
  std::string method;
  std::optional<EvaluateResult> result;
  std::string note;
};

// A method that is not built yet, not applicable here or fails on this geometry is a row of the
// table that says so (shown "-"), not the end of the reproduction.
Outcome evaluate_method(const RegistrationModel& model, const MeasurementSet& set,
                        const std::string& name, const InterpolationChoice& choice) {
  Outcome out{name, std::nullopt, ""};
  try {
    EvaluateOptions options;
    options.interpolation = choice;
    options.exact = true;  // the methods themselves are compared, not their tables
    out.result = evaluate(model, set, options);
  } catch (const std::exception& e) {
    out.note = e.what();
    const std::string source = set.source + ": ";  // the table already says which dataset
    if (out.note.rfind(source, 0) == 0) out.note.erase(0, source.size());
  }
  return out;
}

double rms_of(const Eigen::VectorXd& v) {
  return v.size() == 0 ? 0.0 : std::sqrt(v.squaredNorm() / static_cast<double>(v.size()));
}

Eigen::VectorXd pick(const Eigen::VectorXd& v, const std::vector<std::size_t>& positions) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(positions.size()));
  for (std::size_t k = 0; k < positions.size(); ++k)
    out(static_cast<Eigen::Index>(k)) = v(static_cast<Eigen::Index>(positions[k]));
  return out;
}

// The positions whose orientation was corrected.
std::vector<std::size_t> corrected_positions(const EvaluateResult& r,
                                             const std::vector<std::size_t>& positions) {
  std::vector<std::size_t> out;
  for (const std::size_t k : positions) {
    if (is_corrected(r.orientation->correction.status[k])) out.push_back(k);
  }
  return out;
}

BeyondRow row_of(const Outcome& o, const std::vector<std::size_t>& positions) {
  BeyondRow row;
  row.method = o.method;
  if (!o.result) {
    row.note = o.note;
    return row;
  }
  const EvaluateResult& r = *o.result;
  row.ok = true;
  const Eigen::VectorXd cor = pick(r.cor_tre_m, positions);
  row.cor_rms_t_m = rms_of(cor);
  for (const std::size_t k : positions) {
    if (r.correction.stencils[k].status != StencilStatus::kOk) ++row.n_flagged;
  }
  if (r.correction.predicted_sd_m.size() == r.cor_tre_m.size()) {
    const UncertaintyCalibration c =
        uncertainty_calibration(cor, pick(r.correction.predicted_sd_m, positions));
    if (c.n > 0) {
      row.calibration_rms_ratio = c.rms_ratio;
      row.within_2sigma = c.within_2sigma;
    }
  }
  if (r.cross_validation) row.chosen = to_string(r.cross_validation->chosen);
  if (r.orientation) {
    const std::vector<std::size_t> ok = corrected_positions(r, positions);
    const Eigen::VectorXd angle = pick(r.orientation->cor_error_rad, ok);
    row.cor_rms_angle_rad = rms_of(angle);
    const Eigen::VectorXd& sd = r.orientation->correction.predicted_sd_rad;
    if (sd.size() == r.orientation->cor_error_rad.size()) {
      const UncertaintyCalibration c = uncertainty_calibration(angle, pick(sd, ok));
      if (c.n > 0) row.angle_calibration_rms_ratio = c.rms_ratio;
    }
  }
  return row;
}

// RMS over `rows` of the distance between a location as measured and its noise-free twin
// (`squared` gives its square); `what` names the figure in errors.
template <typename Squared>
double twin_rms(const MeasurementSet& measured, const MeasurementSet& noise_free,
                const std::vector<std::size_t>& rows, const char* what, Squared squared) {
  VRREG_THROW_UNLESS(measured.locations.size() == noise_free.locations.size(),
                     what << ": " << measured.locations.size() << " measured locations but "
                          << noise_free.locations.size() << " noise-free ones");
  if (rows.empty()) return 0.0;
  double sum_sq = 0.0;
  for (const std::size_t i : rows) {
    const Location& a = measured.locations.at(i);
    const Location& b = noise_free.locations.at(i);
    VRREG_THROW_UNLESS(a.point == b.point && a.config == b.config,
                       what << ": location " << i << " is '" << a.point << "' measured but '"
                            << b.point << "' noise-free");
    sum_sq += squared(a, b);
  }
  return std::sqrt(sum_sq / static_cast<double>(rows.size()));
}

}  // namespace

const std::vector<InterpolationMethod>& beyond_field_methods() {
  static const std::vector<InterpolationMethod> methods = {
      InterpolationMethod::kLinear, InterpolationMethod::kScattered, InterpolationMethod::kTrilinear,
      InterpolationMethod::kRbf,    InterpolationMethod::kKriging,   InterpolationMethod::kJoint,
      InterpolationMethod::kAuto};
  return methods;
}

simulation::TestbedErrorModel without_noise(simulation::TestbedErrorModel errors) {
  errors.tracker.noise_sigma_m.setZero();
  errors.robot.repeatability_sigma_m = 0.0;
  return errors;
}

double noise_floor_m(const MeasurementSet& measured, const MeasurementSet& noise_free,
                     const std::vector<std::size_t>& rows) {
  return twin_rms(
      measured, noise_free, rows, "noise floor",
      [](const Location& a, const Location& b) { return (a.sensor_m - b.sensor_m).squaredNorm(); });
}

double angle_noise_floor_rad(const MeasurementSet& measured, const MeasurementSet& noise_free,
                             const std::vector<std::size_t>& rows) {
  return twin_rms(measured, noise_free, rows, "angle noise floor",
                  [](const Location& a, const Location& b) {
                    VRREG_THROW_UNLESS(
                        a.q_sensor_marker && b.q_sensor_marker,
                        "angle noise floor: '" << a.point << "' has no orientation in both sets");
                    return std::pow(rotation_angle_rad(a.q_sensor_marker->toRotationMatrix(),
                                                       b.q_sensor_marker->toRotationMatrix()),
                                    2);
                  });
}

std::vector<BeyondTable> beyond_tables(const MeasurementSet& measured,
                                       const MeasurementSet& noise_free,
                                       const kinematics::SerialChain& robot, double sigma_rep_m,
                                       const std::vector<TargetGroup>& groups,
                                       std::optional<double> octuplet_edge_m,
                                       const std::vector<InterpolationMethod>& methods) {
  // One registration of all fiducials, as Table 1 does; sigma_L is not reported here (slow).
  RegisterOptions reg;
  reg.rigid_body_statistics = false;
  reg.sigma_rep_m = sigma_rep_m;
  reg.robot = robot;
  const RegisterResult registered = register_fiducials(measured, reg);

  std::vector<Outcome> outcomes;
  if (octuplet_edge_m) {
    InterpolationChoice octuplet;
    octuplet.method = InterpolationMethod::kOctuplet;
    octuplet.cube_edge_m = *octuplet_edge_m;
    outcomes.push_back(evaluate_method(registered.model, measured, "octuplet", octuplet));
  }
  for (const InterpolationMethod m : methods.empty() ? beyond_field_methods() : methods) {
    InterpolationChoice choice;
    choice.method = m;
    outcomes.push_back(evaluate_method(registered.model, measured, to_string(m), choice));
  }
  // The uncorrected errors depend on the registration only (Eq. 3), whichever method corrects.
  const std::vector<std::size_t> target_rows = measured.select(Role::kTarget);
  const Eigen::VectorXd unc_tre_m =
      point_errors(registered.model.T_robot_sensor.apply_all(measured.sensor_points(target_rows)),
                   measured.robot_points(target_rows));

  std::vector<BeyondTable> out;
  for (const TargetGroup& g : groups) {
    BeyondTable t;
    t.key = g.key;
    t.dataset = g.dataset;
    t.n_fiducials = static_cast<int>(registered.model.fiducials.size());
    t.n_targets = static_cast<int>(g.positions.size());
    t.unc_rms_t_m = rms_of(pick(unc_tre_m, g.positions));
    std::vector<std::size_t> rows;
    for (const std::size_t k : g.positions) rows.push_back(target_rows.at(k));
    t.noise_floor_m = noise_floor_m(measured, noise_free, rows);
    for (const Outcome& o : outcomes) t.rows.push_back(row_of(o, g.positions));
    // The uncorrected angle errors depend on the registration only, as the positions' do.
    for (const Outcome& o : outcomes) {
      if (!o.result || !o.result->orientation) continue;
      t.unc_rms_angle_rad = rms_of(pick(o.result->orientation->unc_error_rad, g.positions));
      t.angle_noise_floor_rad = angle_noise_floor_rad(measured, noise_free, rows);
      break;
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace vrreg::experiments
