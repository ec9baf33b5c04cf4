// SPDX-License-Identifier: Apache-2.0
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "corrector_json.hpp"
#include "model_chain_json.hpp"
#include "model_marker_offset_json.hpp"
#include "model_monitoring_json.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/progress.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/model_json.hpp"

namespace vrreg::io {
namespace {

using ordered_json = nlohmann::ordered_json;

double finite(double value, const char* key) {
  VRREG_THROW_UNLESS(std::isfinite(value), "model: " << key << " is not finite (" << value << ")");
  return value;
}

ordered_json m_array(const Eigen::Vector3d& v_m, const char* key) {
  ordered_json out = ordered_json::array();
  for (int axis = 0; axis < 3; ++axis) out.push_back(finite(v_m(axis), key));
  return out;
}

ordered_json optional_int(const std::optional<int>& value) {
  return value ? ordered_json(*value) : ordered_json(nullptr);
}

// `approach`: with the fiducial's approach directions (a corrector with a lost-motion term reads
// them when restored).
ordered_json fiducial_json(const Location& f, const Eigen::Vector3d& correction_m, bool approach) {
  ordered_json out = ordered_json::object();
  out["point"] = f.point;
  out["config"] = optional_int(f.config);
  out["robot_m"] = m_array(f.robot_m, "fiducial robot_m");
  out["sensor_m"] = m_array(f.sensor_m, "fiducial sensor_m");
  out["n_readings"] = f.n_readings;
  if (f.source_line > 0) out["line"] = f.source_line;
  out["sensor_sq_dev_m2"] = m_array(f.sensor_sq_dev_m2, "fiducial sensor_sq_dev_m2");
  if (!f.q_rad.empty()) {
    ordered_json q = ordered_json::array();
    for (const double v : f.q_rad) q.push_back(finite(v, "fiducial q_rad"));
    out["q_rad"] = std::move(q);
  }
  if (approach && !f.approach_sign.empty()) {
    ordered_json s = ordered_json::array();
    for (const double v : f.approach_sign) s.push_back(static_cast<int>(v));
    out["approach_sign"] = std::move(s);
  }
  // Rigid-body markers only: a sphere's fiducials keep their keys (orientation_field.hpp).
  const auto quaternion = [](const Eigen::Quaterniond& q, const char* what) {
    ordered_json a = ordered_json::array();
    for (int k = 0; k < 4; ++k) a.push_back(finite(q.coeffs()(k), what));  // x, y, z, w
    return a;
  };
  if (f.q_sensor_marker) {
    out["q_sensor_marker"] = quaternion(*f.q_sensor_marker, "fiducial q_sensor_marker");
    out["orientation_sq_dev_rad2"] = finite(f.orientation_sq_dev_rad2, "fiducial orientation");
  }
  if (f.q_robot_marker) {
    out["q_robot_marker"] = quaternion(*f.q_robot_marker, "fiducial q_robot_marker");
  }
  out["correction_m"] = m_array(correction_m, "fiducial correction_m");
  return out;
}

// Present only when sigma_L was estimated from a sample of pairs (absent: all pairs).
ordered_json sampling_json(const SigmaLSampling& s) {
  return {{"pairs", s.pairs_sampled},
          {"pairs_total", s.pairs_total},
          {"seed", s.seed},
          {"confidence", finite(s.confidence, "sigma_l_sampling.confidence")},
          {"interval_m",
           {finite(s.sigma_l_low_m, "sigma_l_sampling.interval_m"),
            finite(s.sigma_l_high_m, "sigma_l_sampling.interval_m")}}};
}

// Procedure 2 (paper section 4.4): written only for models built with a strategy.
ordered_json procedure2_json(const RegistrationModel& model) {
  const planning::Procedure2& p = model.procedure2;
  ordered_json out = ordered_json::object();
  out["strategy"] = planning::strategy_number(p.strategy);
  out["joint_norm"] = kinematics::to_string(p.joint_norm);
  if (p.seed) out["seed"] = *p.seed;
  if (!p.registration_fiducials.empty()) {
    for (const std::size_t j : p.registration_fiducials) {
      VRREG_THROW_UNLESS(j < model.fiducials.size(),
                         "model: registration fiducial " << j << " of " << model.fiducials.size());
    }
    out["registration_fiducials"] = p.registration_fiducials;
  }
  return out;
}

}  // namespace

std::string format_model_json(const RegistrationModel& model) {
  VRREG_THROW_UNLESS(
      model.corrections_sensor_m.cols() == static_cast<Eigen::Index>(model.fiducials.size()),
      "model: " << model.corrections_sensor_m.cols() << " corrections for "
                << model.fiducials.size() << " fiducials");
  // What the reader refuses: a joint-space model without its robot or a fiducial's joints.
  if (model.interpolation.method == InterpolationMethod::kJoint) {
    VRREG_THROW_UNLESS(model.robot, "model: a joint-space model needs its robot");
    for (const Location& f : model.fiducials) {
      VRREG_THROW_UNLESS(f.q_rad.size() == static_cast<std::size_t>(model.robot->n_joints()),
                         "model: fiducial '" << f.point << "' has " << f.q_rad.size()
                                             << " joint angles, robot '" << model.robot->name()
                                             << "' " << model.robot->n_joints());
    }
  }
  const SimilarityTransform& T = model.T_robot_sensor;
  ordered_json out = ordered_json::object();
  out["format"] = "vrreg-model";
  out["version"] = RegistrationModel::kFormatVersion;
  out["units"] = {{"length", "m"}, {"angle", "rad"}};
  ordered_json rotation = ordered_json::array();
  for (int r = 0; r < 3; ++r) {
    ordered_json row = ordered_json::array();
    for (int c = 0; c < 3; ++c) row.push_back(finite(T.rotation(r, c), "rotation"));
    rotation.push_back(std::move(row));
  }
  out["rotation"] = std::move(rotation);
  out["translation_m"] = m_array(T.translation_m, "translation_m");
  out["scale"] = finite(T.scale, "scale");
  out["fre_m"] = finite(model.fre_m, "fre_m");
  out["sigma_l_m"] = finite(model.sigma_l_m, "sigma_l_m");
  if (model.sigma_l_sampling.sampled)
    out["sigma_l_sampling"] = sampling_json(model.sigma_l_sampling);
  if (model.sigma_rep_m)
    out["sigma_rep_m"] = finite(*model.sigma_rep_m, "sigma_rep_m");
  out["config"] = optional_int(model.config);
  if (model.procedure2.strategy != planning::Strategy::kNone)
    out["procedure2"] = procedure2_json(model);
  out["source"] = model.source;
  if (model.marker_offset) out["marker_offset"] = detail::marker_offset_json(*model.marker_offset);
  if (model.robot) out["robot"] = detail::chain_json(*model.robot, true, "robot");
  out["interpolation"] = {
      {"method", to_string(model.interpolation.method)},
      {"cube_m", finite(model.interpolation.cube_edge_m, "cube_m")},
      {"match_tolerance_m", finite(model.interpolation.match_tolerance_m, "match_tolerance_m")}};
  // Only a model whose corrector applies a lost-motion term keeps the approach directions: the
  // other models' files stay as they were.
  const bool approach = model.corrector && model.corrector->lost_motion() &&
                        model.corrector->lost_motion()->applied;
  ordered_json fiducials = ordered_json::array();
  for (std::size_t j = 0; j < model.fiducials.size(); ++j) {
    fiducials.push_back(fiducial_json(model.fiducials[j],
                                      model.corrections_sensor_m.col(static_cast<Eigen::Index>(j)),
                                      approach));
  }
  // The correctors were fitted on these fiducials: the reader refuses them once they changed.
  const std::string fiducials_fingerprint =
      model.corrector || model.orientation_corrector ? detail::json_fingerprint(fiducials) : "";
  out["fiducials"] = std::move(fiducials);
  detail::add_monitoring_json(model, out);
  if (model.corrector) {
    out["corrector"] = detail::corrector_json(model.corrector->save(), fiducials_fingerprint);
  }
  if (model.orientation_corrector) {
    out["orientation_corrector"] = detail::orientation_corrector_json(
        model.orientation_corrector->save(), fiducials_fingerprint);
  }
  try {
    return out.dump(2) + "\n";
  } catch (const ordered_json::type_error& e) {  // invalid UTF-8 in a label or the source name
    VRREG_THROW_UNLESS(false, "model: cannot write as JSON: " << e.what());
  }
}

void write_model_json(const std::string& path, const RegistrationModel& model) {
  // A large cell's model (10^6 fiducials) takes seconds to format and write.
  ProgressStage progress("writing " + std::filesystem::path(path).filename().string(), 2);
  const std::string text = format_model_json(model);
  progress.advance();
  write_file_atomically(path, text);
  progress.advance();
}

}  // namespace vrreg::io
