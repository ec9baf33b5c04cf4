// SPDX-License-Identifier: Apache-2.0
#include "corrector_json.hpp"

#include <cmath>
#include <limits>

#include "base64_doubles.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/configuration_order.hpp"

namespace vrreg::io::detail {
namespace {

using ojson = nlohmann::ordered_json;
using nlohmann::json;

// Arrays of this many values or more are written as base64 of their bytes (a table of 10^4
// nodes: ~0.5 MB instead of ~5 MB of indented decimals, and read without parsing each number).
constexpr Eigen::Index kBinaryFrom = 1024;

const char* sd_source_name(SdSource s) {
  switch (s) {
    case SdSource::kNone: return "none";
    case SdSource::kModel: return "model";
    case SdSource::kLocalCv: return "local_cv";
    case SdSource::kGlobalCv: return "global_cv";
  }
  return "none";
}

double finite(double v, const std::string& what) {
  VRREG_THROW_UNLESS(std::isfinite(v), "model: corrector " << what << " is not finite (" << v << ")");
  return v;
}

// NaN (not predicted) as null: JSON has no NaN.
ojson with_nulls(const Eigen::VectorXd& v) {
  ojson out = ojson::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (std::isnan(v(i))) {
      out.push_back(nullptr);
    } else {
      out.push_back(finite(v(i), "held-out error"));
    }
  }
  return out;
}

Eigen::VectorXd read_with_nulls(const json& list, const std::string& path, const JsonFields& f) {
  if (!list.is_array()) f.fail(path, "expected an array of numbers and nulls");
  Eigen::VectorXd out(static_cast<Eigen::Index>(list.size()));
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& v = list[i];
    if (v.is_null()) {
      out(static_cast<Eigen::Index>(i)) = std::numeric_limits<double>::quiet_NaN();
    } else if (v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() >= 0.0) {
      out(static_cast<Eigen::Index>(i)) = v.get<double>();
    } else {
      f.fail(path + "[" + std::to_string(i) + "]", "expected a number >= 0 or null");
    }
  }
  return out;
}

ojson settings_json(const InterpolationSettings& s) {
  return {{"method", to_string(s.method)},
          {"cube_m", finite(s.cube_edge_m, "cube edge")},
          {"match_tolerance_m", finite(s.match_tolerance_m, "match tolerance")}};
}

InterpolationSettings read_settings(const json& item, const std::string& path, const JsonFields& f) {
  InterpolationSettings s;
  try {
    s.method = parse_interpolation_method(f.string(item, path, "method"));
  } catch (const InputError& e) {
    f.fail(join_path(path, "method"), e.what());
  }
  s.cube_edge_m = f.number(item, path, "cube_m");
  s.match_tolerance_m = f.number(item, path, "match_tolerance_m");
  try {
    s.validate();
  } catch (const InputError& e) {
    f.fail(path, e.what());
  }
  return s;
}

ojson table_json(const CrossValidation& cv) {
  ojson out = ojson::object();
  out["folds"] = cv.folds;
  out["seed"] = cv.seed;
  out["n_common"] = cv.n_common;
  out["n_units"] = cv.n_units;
  out["chosen"] = to_string(cv.chosen);
  ojson rows = ojson::array();
  for (const CrossValidationRow& r : cv.rows) {
    ojson row = ojson::object();
    row["method"] = to_string(r.method);
    row["applicable"] = r.applicable;
    row["note"] = r.note;
    row["rms_m"] = finite(r.rms_m, "cv rms");
    row["rms_axis_m"] = {finite(r.rms_axis_m.x(), "cv rms"), finite(r.rms_axis_m.y(), "cv rms"),
                         finite(r.rms_axis_m.z(), "cv rms")};
    row["n_predicted"] = r.n_predicted;
    row["rms_common_m"] = finite(r.rms_common_m, "cv rms");
    rows.push_back(std::move(row));
  }
  out["rows"] = std::move(rows);
  return out;
}

InterpolationMethod read_method(const json& item, const std::string& path, const std::string& key,
                                const JsonFields& f) {
  try {
    return parse_interpolation_method(f.string(item, path, key));
  } catch (const InputError& e) {
    f.fail(join_path(path, key), e.what());
  }
}

Eigen::Index read_count(const json& item, const std::string& path, const std::string& key,
                        const JsonFields& f) {
  const json& v = f.member(item, path, key);
  if (!v.is_number_unsigned()) f.fail(join_path(path, key), "expected a whole number >= 0");
  return static_cast<Eigen::Index>(v.get<std::uint64_t>());
}

CrossValidation read_table(const json& item, const std::string& path, const JsonFields& f) {
  f.require_object(item, path);
  CrossValidation cv;
  cv.folds = f.integer(item, path, "folds");
  const json& seed = f.member(item, path, "seed");
  if (!seed.is_number_unsigned()) f.fail(join_path(path, "seed"), "expected a whole number >= 0");
  cv.seed = seed.get<std::uint64_t>();
  cv.n_common = read_count(item, path, "n_common", f);
  cv.n_units = read_count(item, path, "n_units", f);
  cv.chosen = read_method(item, path, "chosen", f);
  const json& rows = f.member(item, path, "rows");
  if (!rows.is_array()) f.fail(join_path(path, "rows"), "expected an array");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string at = join_path(path, "rows") + "[" + std::to_string(i) + "]";
    const json& r = rows[i];
    CrossValidationRow row;
    row.method = read_method(r, at, "method", f);
    const json& applicable = f.member(r, at, "applicable");
    if (!applicable.is_boolean()) f.fail(join_path(at, "applicable"), "expected true or false");
    row.applicable = applicable.get<bool>();
    row.note = f.string(r, at, "note");
    row.rms_m = f.number(r, at, "rms_m");
    const std::vector<double> axis = f.numbers(r, at, "rms_axis_m", 3);
    row.rms_axis_m = Eigen::Vector3d(axis[0], axis[1], axis[2]);
    row.n_predicted = read_count(r, at, "n_predicted", f);
    row.rms_common_m = f.number(r, at, "rms_common_m");
    cv.rows.push_back(std::move(row));
  }
  return cv;
}

ojson state_json(const MethodState& state) {
  ojson out = ojson::object();
  for (const auto& [key, value] : state.arrays()) {
    VRREG_THROW_UNLESS(value.allFinite(), "model: corrector state '" << key << "' is not finite");
    if (value.rows() == 1 && value.cols() == 1) {
      out[key] = value(0, 0);
      continue;
    }
    if (value.size() >= kBinaryFrom) {  // column-major, as Eigen stores it
      out[key] = {{"shape", {value.rows(), value.cols()}},
                  {"f64le_base64", doubles_to_base64(value.data(), static_cast<std::size_t>(value.size()))}};
      continue;
    }
    ojson values = ojson::array();
    for (Eigen::Index c = 0; c < value.cols(); ++c) {
      for (Eigen::Index r = 0; r < value.rows(); ++r) values.push_back(value(r, c));
    }
    out[key] = {{"shape", {value.rows(), value.cols()}}, {"values", std::move(values)}};
  }
  for (const auto& [key, text] : state.texts()) out[key] = text;
  return out;
}

MethodState read_state(const json& item, const std::string& path, const std::string& method,
                       const JsonFields& f) {
  f.require_object(item, path);
  MethodState state(method);
  for (const auto& [key, value] : item.items()) {
    const std::string at = join_path(path, key);
    if (value.is_string()) {
      state.put_text(key, value.get<std::string>());
    } else if (value.is_number()) {
      state.put(key, f.number(item, path, key));
    } else if (value.is_object()) {
      const std::vector<double> shape = f.numbers(value, at, "shape", 2);
      for (const double d : shape) {
        if (d < 0 || d != std::floor(d) || d > 1e9) f.fail(join_path(at, "shape"), "expected two whole numbers");
      }
      const auto rows = static_cast<Eigen::Index>(shape[0]);
      const auto cols = static_cast<Eigen::Index>(shape[1]);
      std::vector<double> values;
      if (value.contains("f64le_base64")) {
        const json& text = value.at("f64le_base64");
        std::optional<std::vector<double>> decoded;
        if (text.is_string()) decoded = base64_to_doubles(text.get<std::string>());
        if (!decoded) f.fail(join_path(at, "f64le_base64"), "not base64 of 8-byte values");
        values = std::move(*decoded);
        for (const double v : values) {
          if (!std::isfinite(v)) f.fail(join_path(at, "f64le_base64"), "holds a value that is not finite");
        }
      } else {
        values = f.numbers(value, at, "values", -1);
      }
      if (static_cast<double>(values.size()) != shape[0] * shape[1]) {
        f.fail(join_path(at, "values"), "expected " + std::to_string(rows * cols) + " numbers");
      }
      state.put(key, Eigen::Map<const Eigen::MatrixXd>(values.data(), rows, cols));
    } else {
      f.fail(at, std::string("expected a number, a text or a shaped array, found ") +
                     value.type_name());
    }
  }
  return state;
}

}  // namespace

ojson corrector_json(const SavedCorrector& saved) {
  ojson out = ojson::object();
  out["method"] = to_string(saved.method);
  out["requested"] = settings_json(saved.requested);
  if (saved.nearest_configuration) {
    out["nearest_configuration"] = kinematics::to_string(*saved.nearest_configuration);
  }
  out["cv_folds"] = saved.cv_folds;
  out["cv_seed"] = saved.cv_seed;
  out["sd_source"] = sd_source_name(saved.sd_source);
  out["cv_rms_m"] = finite(saved.cv_rms_m, "cv rms");
  if (saved.cv_squared_error_m2.size() > 0) {
    out["cv_squared_error_m2"] = with_nulls(saved.cv_squared_error_m2);
  }
  if (saved.cross_validation) out["cross_validation"] = table_json(*saved.cross_validation);
  out["state"] = state_json(saved.state);
  return out;
}

SavedCorrector read_corrector(const json& item, const std::string& path, const JsonFields& f) {
  f.require_object(item, path);
  SavedCorrector out;
  out.method = read_method(item, path, "method", f);
  out.requested = read_settings(f.member(item, path, "requested"), join_path(path, "requested"), f);
  if (item.contains("nearest_configuration")) {
    const std::string norm = f.string(item, path, "nearest_configuration");
    if (norm != "l2" && norm != "linf") {
      f.fail(join_path(path, "nearest_configuration"), "expected \"l2\" or \"linf\"");
    }
    out.nearest_configuration = kinematics::parse_joint_norm(norm);
  }
  out.cv_folds = f.integer(item, path, "cv_folds");
  if (out.cv_folds < 2) f.fail(join_path(path, "cv_folds"), "must be at least 2");
  const json& seed = f.member(item, path, "cv_seed");
  if (!seed.is_number_unsigned()) f.fail(join_path(path, "cv_seed"), "expected a whole number >= 0");
  out.cv_seed = seed.get<std::uint64_t>();
  const std::string sd = f.string(item, path, "sd_source");
  bool known = false;
  for (const SdSource s : {SdSource::kNone, SdSource::kModel, SdSource::kLocalCv, SdSource::kGlobalCv}) {
    if (sd == sd_source_name(s)) {
      out.sd_source = s;
      known = true;
    }
  }
  if (!known) f.fail(join_path(path, "sd_source"), "expected none, model, local_cv or global_cv");
  out.cv_rms_m = f.number(item, path, "cv_rms_m");
  if (out.cv_rms_m < 0.0) f.fail(join_path(path, "cv_rms_m"), "negative");
  if (item.contains("cv_squared_error_m2")) {
    out.cv_squared_error_m2 =
        read_with_nulls(item.at("cv_squared_error_m2"), join_path(path, "cv_squared_error_m2"), f);
  }
  if (item.contains("cross_validation")) {
    out.cross_validation =
        read_table(item.at("cross_validation"), join_path(path, "cross_validation"), f);
  }
  out.state = read_state(f.member(item, path, "state"), join_path(path, "state"),
                         to_string(out.method), f);
  return out;
}

nlohmann::ordered_json orientation_corrector_json(const SavedOrientationCorrector& saved) {
  nlohmann::ordered_json out;
  out["method"] = to_string(saved.method);
  nlohmann::ordered_json mean = nlohmann::ordered_json::array();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) mean.push_back(finite(saved.mean_residual(r, c), "mean residual"));
  out["mean_residual"] = std::move(mean);
  out["joint_rms_rad"] = finite(saved.joint_rms_rad, "joint rms");
  if (saved.joint_terms.degree >= 0 || saved.joint_terms.link_rotations_rad.size() > 0) {
    const JointRotationTerms& t = saved.joint_terms;
    const auto list = [](const Eigen::VectorXd& v) {
      nlohmann::ordered_json a = nlohmann::ordered_json::array();
      for (const double x : v) a.push_back(finite(x, "joint terms"));
      return a;
    };
    out["joint_terms"] = {{"degree", t.degree},
                          {"q_lo_rad", list(t.q_lo_rad)},
                          {"q_hi_rad", list(t.q_hi_rad)},
                          {"coefficients", list(t.coefficients)}};
    if (t.link_rotations_rad.size() > 0) {
      out["joint_terms"]["link_rotations_rad"] = list(t.link_rotations_rad);
    }
  }
  if (saved.tangent) out["tangent"] = corrector_json(*saved.tangent);
  return out;
}

SavedOrientationCorrector read_orientation_corrector(const json& item, const std::string& path,
                                                     const JsonFields& f) {
  f.require_object(item, path);
  SavedOrientationCorrector out;
  out.method = read_method(item, path, "method", f);
  const std::vector<double> mean = f.numbers(item, path, "mean_residual", 9);  // row-major
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.mean_residual(r, c) = mean[static_cast<std::size_t>(3 * r + c)];
  out.joint_rms_rad = f.number(item, path, "joint_rms_rad");
  if (out.joint_rms_rad < 0.0) f.fail(join_path(path, "joint_rms_rad"), "negative");
  if (item.contains("joint_terms")) {
    const std::string at = join_path(path, "joint_terms");
    const json& t = item.at("joint_terms");
    f.require_object(t, at);
    const auto vector = [&](const char* key) {
      const std::vector<double> v = f.numbers(t, at, key, -1);
      return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(v.data(), std::ssize(v)));
    };
    out.joint_terms.degree = f.integer(t, at, "degree");
    if (out.joint_terms.degree < -1) f.fail(join_path(at, "degree"), "below -1 (none)");
    out.joint_terms.q_lo_rad = vector("q_lo_rad");
    out.joint_terms.q_hi_rad = vector("q_hi_rad");
    out.joint_terms.coefficients = vector("coefficients");
    if (t.contains("link_rotations_rad")) {
      out.joint_terms.link_rotations_rad = vector("link_rotations_rad");
    }
  }
  if (item.contains("tangent")) {
    out.tangent = read_corrector(item.at("tangent"), join_path(path, "tangent"), f);
  } else if (out.method != InterpolationMethod::kJoint) {
    f.fail(join_path(path, "tangent"), "missing (every method but joint has one)");
  }
  return out;
}

}  // namespace vrreg::io::detail
