// SPDX-License-Identifier: Apache-2.0
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "corrector_json.hpp"
#include "json_fields.hpp"
#include "model_chain_json.hpp"
#include "model_marker_offset_json.hpp"
#include "model_monitoring_json.hpp"
#include "model_units.hpp"
#include "vrreg/core/progress.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/input_file.hpp"
#include "vrreg/io/json_text.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/kinematics/configuration_order.hpp"

namespace vrreg::io {
namespace {

using nlohmann::json;
using detail::LengthUnits;
constexpr double kRotationTolerance = 1e-9;

json parse_document(const std::string& text, const std::string& source) {
  return parse_json_document(text, source, "model file");
}

// The file's version and its length unit: version 1 wrote millimetres, version 2 metres.
LengthUnits check_header(const json& doc, const detail::JsonFields& f, const std::string& source) {
  f.require_object(doc, "");
  const json& format = f.member(doc, "", "format");
  if (!format.is_string() || format.get<std::string>() != "vrreg-model") {
    throw FileError(source, 0,
                    "not a vrreg model file (\"format\" is " + quote_value(format) +
                        ", expected \"vrreg-model\")");
  }
  const json& version = f.member(doc, "", "version");
  if (!version.is_number_integer() || version.get<std::int64_t>() < 1 ||
      version.get<std::int64_t>() > RegistrationModel::kFormatVersion) {
    throw FileError(source, 0,
                    "unsupported model version " + quote_value(version) +
                        "; this vrreg reads versions 1 to " +
                        std::to_string(RegistrationModel::kFormatVersion));
  }
  const bool v1 = version.get<std::int64_t>() == 1;
  const json& units = f.member(doc, "", "units");
  if (f.string(units, "units", "length") != (v1 ? "mm" : "m")) {
    f.fail("units.length", v1 ? "expected \"mm\"" : "expected \"m\"");
  }
  if (f.string(units, "units", "angle") != "rad") f.fail("units.angle", "expected \"rad\"");
  return v1 ? detail::kMillimetres : detail::kMetres;
}

Eigen::Matrix3d read_rotation(const json& doc, const detail::JsonFields& f) {
  const json& rows = f.member(doc, "", "rotation");
  if (!rows.is_array() || rows.size() != 3) f.fail("rotation", "expected 3 rows of 3 numbers");
  Eigen::Matrix3d R;
  for (int r = 0; r < 3; ++r) {
    const std::vector<double> row = f.array_of_numbers(rows[static_cast<std::size_t>(r)],
                                                       "rotation[" + std::to_string(r) + "]", 3);
    for (int c = 0; c < 3; ++c) R(r, c) = row[static_cast<std::size_t>(c)];
  }
  const double orthogonality =
      (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  const double det = R.determinant();
  if (orthogonality > kRotationTolerance || det < 0.0) {
    std::ostringstream message;
    message << "not a proper rotation (max |R'R - I| = " << orthogonality << ", det = " << det
            << ")";
    f.fail("rotation", message.str());
  }
  return R;
}

Location read_fiducial(const json& item, const std::string& path, const detail::JsonFields& f,
                       const LengthUnits& u, Eigen::Vector3d& correction_m) {
  Location loc;
  loc.role = Role::kFiducial;
  loc.has_robot = true;
  loc.point = f.string(item, path, "point");
  if (loc.point.empty()) f.fail(detail::join_path(path, "point"), "empty point label");
  loc.config = f.optional_integer(item, path, "config");
  loc.robot_m = f.vector3(item, path, u.key("robot"), u.per_m);
  loc.sensor_m = f.vector3(item, path, u.key("sensor"), u.per_m);
  loc.n_readings = f.integer(item, path, "n_readings");
  if (loc.n_readings < 1) f.fail(detail::join_path(path, "n_readings"), "must be at least 1");
  loc.sensor_sq_dev_m2 = f.vector3(item, path, u.area_key("sensor_sq_dev"), u.per_m * u.per_m);
  if (loc.sensor_sq_dev_m2.minCoeff() < 0.0)
    f.fail(detail::join_path(path, u.area_key("sensor_sq_dev")), "negative");
  if (item.contains("line")) {
    const int line = f.integer(item, path, "line");
    if (line < 1) f.fail(detail::join_path(path, "line"), "must be at least 1");
    loc.source_line = static_cast<std::size_t>(line);
  }
  if (item.contains("q_rad")) loc.q_rad = f.numbers(item, path, "q_rad", -1);
  if (item.contains("approach_sign")) {
    loc.approach_sign = f.numbers(item, path, "approach_sign", static_cast<int>(loc.q_rad.size()));
    for (const double v : loc.approach_sign) {
      if (v != -1.0 && v != 0.0 && v != 1.0)
        f.fail(detail::join_path(path, "approach_sign"), "expected signs -1, 0 or 1");
    }
  }
  const auto quaternion = [&](const char* key) {
    const std::vector<double> c = f.numbers(item, path, key, 4);  // x, y, z, w
    const Eigen::Quaterniond q(c[3], c[0], c[1], c[2]);
    if (!(std::abs(q.norm() - 1.0) <= 1e-6)) {
      f.fail(detail::join_path(path, key),
             "not a unit quaternion (norm " + std::to_string(q.norm()) + ")");
    }
    // What register wrote is unit to rounding: kept to the bit, so a model read back corrects
    // exactly as the one written; anything further off is normalised.
    return std::abs(q.norm() - 1.0) <= kUnitQuaternionRounding ? q : q.normalized();
  };
  if (item.contains("q_sensor_marker")) {
    loc.q_sensor_marker = quaternion("q_sensor_marker");
    loc.orientation_sq_dev_rad2 = f.number(item, path, "orientation_sq_dev_rad2");
    if (loc.orientation_sq_dev_rad2 < 0.0)
      f.fail(detail::join_path(path, "orientation_sq_dev_rad2"), "negative");
  }
  if (item.contains("q_robot_marker")) {
    if (!loc.q_sensor_marker)
      f.fail(detail::join_path(path, "q_robot_marker"), "given without q_sensor_marker");
    loc.q_robot_marker = quaternion("q_robot_marker");
  }
  correction_m = f.vector3(item, path, u.key("correction"), u.per_m);
  return loc;
}

// Procedure 2 settings (paper section 4.4); absent in models built without a strategy.
planning::Procedure2 read_procedure2(const json& doc, const detail::JsonFields& f,
                                     std::size_t n_fiducials) {
  planning::Procedure2 p;
  if (!doc.contains("procedure2")) return p;
  const json& item = f.member(doc, "", "procedure2");
  f.require_object(item, "procedure2");
  const int strategy = f.integer(item, "procedure2", "strategy");
  if (strategy < 0 || strategy > 3) f.fail("procedure2.strategy", "expected 0, 1, 2 or 3");
  p.strategy = planning::strategy_from_number(strategy);
  const std::string norm = f.string(item, "procedure2", "joint_norm");
  if (norm != "l2" && norm != "linf") {
    f.fail("procedure2.joint_norm", "expected \"l2\" or \"linf\"");
  }
  p.joint_norm = kinematics::parse_joint_norm(norm);
  if (item.contains("seed")) {
    const json& seed = item.at("seed");
    if (!seed.is_number_unsigned()) f.fail("procedure2.seed", "expected an integer >= 0");
    p.seed = seed.get<std::uint64_t>();
  }
  if (item.contains("registration_fiducials")) {
    const json& list = item.at("registration_fiducials");
    if (!list.is_array()) f.fail("procedure2.registration_fiducials", "expected an array");
    for (const json& j : list) {
      if (!j.is_number_unsigned() || j.get<std::uint64_t>() >= n_fiducials) {
        f.fail("procedure2.registration_fiducials",
               "expected fiducial indices below " + std::to_string(n_fiducials));
      }
      p.registration_fiducials.push_back(static_cast<std::size_t>(j.get<std::uint64_t>()));
    }
  }
  return p;
}

// sigma_l_sampling: how a sampled sigma_L was estimated (model_json.hpp).
SigmaLSampling read_sampling(const json& doc, const detail::JsonFields& f, const LengthUnits& u) {
  const json& s = f.member(doc, "", "sigma_l_sampling");
  f.require_object(s, "sigma_l_sampling");
  const auto count = [&](const char* key) {
    const double v = f.number(s, "sigma_l_sampling", key);
    if (v < 2.0 || v > 9e15 || v != std::floor(v)) {
      f.fail(detail::join_path("sigma_l_sampling", key), "must be a whole number >= 2");
    }
    return static_cast<std::int64_t>(v);
  };
  SigmaLSampling out;
  out.sampled = true;
  out.pairs_sampled = count("pairs");
  out.pairs_total = count("pairs_total");
  const json& seed = f.member(s, "sigma_l_sampling", "seed");
  if (!seed.is_number_unsigned()) f.fail("sigma_l_sampling.seed", "must be a whole number >= 0");
  out.seed = seed.get<std::uint64_t>();
  out.confidence = f.number(s, "sigma_l_sampling", "confidence");
  if (!(out.confidence > 0.0 && out.confidence < 1.0)) {
    f.fail("sigma_l_sampling.confidence", "must be in (0, 1)");
  }
  const std::vector<double> interval = f.numbers(s, "sigma_l_sampling", u.key("interval"), 2);
  if (interval[0] < 0.0 || interval[1] < interval[0]) {
    f.fail("sigma_l_sampling." + u.key("interval"), "must be [low, high] with 0 <= low <= high");
  }
  out.sigma_l_low_m = interval[0] / u.per_m;
  out.sigma_l_high_m = interval[1] / u.per_m;
  return out;
}

// A joint-space model needs the robot and, on every fiducial, as many joint angles as the robot
// has. Checked here, so that a damaged model file is named, not the targets it is later evaluated
// on. (Other models do not use joints, and may hold them on some fiducials only.)
void check_joint_model(const RegistrationModel& model, const detail::JsonFields& f) {
  if (model.interpolation.method != InterpolationMethod::kJoint) return;
  if (!model.robot) {
    f.fail("robot",
           "missing key: a joint-space model (interpolation 'joint') needs the robot its "
           "fiducials' joint angles are for");
  }
  const auto n_joints = static_cast<std::size_t>(model.robot->n_joints());
  for (std::size_t j = 0; j < model.fiducials.size(); ++j) {
    const std::size_t n = model.fiducials[j].q_rad.size();
    if (n == n_joints) continue;
    f.fail("fiducials[" + std::to_string(j) + "].q_rad",
           (n == 0 ? std::string("missing key") : std::to_string(n) + " joint angles") +
               ": a joint-space model needs the joint angles of every fiducial, " +
               std::to_string(n_joints) + " for robot '" + model.robot->name() + "'");
  }
}

}  // namespace

RegistrationModel parse_model_json(const std::string& text, const std::string& source) {
  const json doc = parse_document(text, source);
  const detail::JsonFields f(source);
  const LengthUnits u = check_header(doc, f, source);
  RegistrationModel model;
  model.T_robot_sensor.rotation = read_rotation(doc, f);
  model.T_robot_sensor.translation_m = f.vector3(doc, "", u.key("translation"), u.per_m);
  model.T_robot_sensor.scale = f.number(doc, "", "scale");
  if (model.T_robot_sensor.scale <= 0.0) f.fail("scale", "must be positive");
  model.fre_m = f.number(doc, "", u.key("fre")) / u.per_m;
  model.sigma_l_m = f.number(doc, "", u.key("sigma_l")) / u.per_m;
  if (model.fre_m < 0.0) f.fail(u.key("fre"), "negative");
  if (model.sigma_l_m < 0.0) f.fail(u.key("sigma_l"), "negative");
  if (doc.contains("sigma_l_sampling")) model.sigma_l_sampling = read_sampling(doc, f, u);
  model.config = f.optional_integer(doc, "", "config");
  if (doc.contains(u.key("sigma_rep"))) {
    model.sigma_rep_m = f.number(doc, "", u.key("sigma_rep")) / u.per_m;
    if (*model.sigma_rep_m < 0.0) f.fail(u.key("sigma_rep"), "negative");
  }
  model.source = f.string(doc, "", "source");
  const json& interp = f.member(doc, "", "interpolation");
  const std::string method = f.string(interp, "interpolation", "method");
  try {
    model.interpolation.method = parse_interpolation_method(method, /*legacy_auto=*/u.per_m != 1.0);
  } catch (const InputError& e) {
    f.fail("interpolation.method", e.what());
  }
  model.interpolation.cube_edge_m = f.number(interp, "interpolation", u.key("cube")) / u.per_m;
  model.interpolation.match_tolerance_m =
      f.number(interp, "interpolation", u.key("match_tolerance")) / u.per_m;
  if (model.interpolation.cube_edge_m < 0.0) f.fail("interpolation." + u.key("cube"), "negative");
  if (model.interpolation.match_tolerance_m < 0.0) {
    f.fail("interpolation." + u.key("match_tolerance"), "negative");
  }
  const json& fiducials = f.member(doc, "", "fiducials");
  if (!fiducials.is_array())
    f.fail("fiducials", std::string("expected an array, found ") + fiducials.type_name());
  model.fiducials.reserve(fiducials.size());
  model.corrections_sensor_m.resize(3, static_cast<Eigen::Index>(fiducials.size()));
  for (std::size_t j = 0; j < fiducials.size(); ++j) {
    Eigen::Vector3d correction_m;
    model.fiducials.push_back(
        read_fiducial(fiducials[j], "fiducials[" + std::to_string(j) + "]", f, u, correction_m));
    model.corrections_sensor_m.col(static_cast<Eigen::Index>(j)) = correction_m;
  }
  model.procedure2 = read_procedure2(doc, f, model.fiducials.size());
  if (doc.contains("marker_offset")) {
    model.marker_offset =
        detail::read_marker_offset(doc.at("marker_offset"), "marker_offset", f, u);
  }
  if (doc.contains("robot")) model.robot = detail::read_chain(doc.at("robot"), "robot", f);
  detail::read_monitoring(doc, f, u, model);
  check_joint_model(model, f);
  const std::string fiducials_fingerprint =
      doc.contains("corrector") || doc.contains("orientation_corrector")
          ? detail::json_fingerprint(fiducials)
          : "";
  if (doc.contains("corrector")) {
    const SavedCorrector saved =
        detail::read_corrector(doc.at("corrector"), "corrector", f, fiducials_fingerprint);
    try {
      model.validate();
      model.corrector = restore_corrector(model, saved);
    } catch (const FileError&) {
      throw;
    } catch (const InputError& e) {
      f.fail("corrector", e.what());
    }
  }
  if (doc.contains("orientation_corrector")) {
    const SavedOrientationCorrector saved = detail::read_orientation_corrector(
        doc.at("orientation_corrector"), "orientation_corrector", f, fiducials_fingerprint);
    try {
      model.orientation_corrector = restore_orientation_corrector(model, saved);
    } catch (const FileError&) {
      throw;
    } catch (const InputError& e) {
      f.fail("orientation_corrector", e.what());
    }
  }
  return model;
}

RegistrationModel read_model_json(const std::string& path) {
  // A large cell's model holds 10^5-10^6 fiducials: seconds to parse.
  const ProgressStage progress("reading " + std::filesystem::path(path).filename().string(), 1);
  return parse_model_json(read_input_file(path), path);
}

}  // namespace vrreg::io
