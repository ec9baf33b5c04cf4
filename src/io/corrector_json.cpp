// SPDX-License-Identifier: Apache-2.0
#include "corrector_json.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "base64_doubles.hpp"
#include "guard_json.hpp"
#include "lost_motion_json.hpp"
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
  out["n_ranked"] = cv.n_ranked;
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
    row["rms_ranked_m"] = finite(r.rms_ranked_m, "cv rms");
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
  // Models saved before the ranking counted misses name the figures for the common subset.
  const bool ranked = item.contains("n_ranked");
  cv.n_ranked = read_count(item, path, ranked ? "n_ranked" : "n_common", f);
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
    row.rms_ranked_m = f.number(r, at, ranked ? "rms_ranked_m" : "rms_common_m");
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

// FNV-1a, 64 bits: a fingerprint against edits, not against an adversary (who could rewrite it).
class Fnv1a64 {
 public:
  void bytes(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) hash_ = (hash_ ^ p[i]) * 0x100000001b3ULL;
  }
  void tag(char c) { bytes(&c, 1); }
  void text(const std::string& s) {
    const std::uint64_t n = s.size();
    bytes(&n, sizeof n);
    bytes(s.data(), s.size());
  }
  [[nodiscard]] std::string hex() const {
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(hash_));
    return out;
  }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

// Members in key order (an ordered_json keeps the writer's order, a json sorts), numbers by their
// value as a double (the text of a number read back may differ, its value does not).
template <typename Json>
void fingerprint_into(const Json& value, Fnv1a64& h) {
  switch (value.type()) {
    case nlohmann::json::value_t::object: {
      std::vector<std::pair<const std::string*, const Json*>> members;
      members.reserve(value.size());
      for (auto it = value.begin(); it != value.end(); ++it) members.emplace_back(&it.key(), &*it);
      std::sort(members.begin(), members.end(),
                [](const auto& a, const auto& b) { return *a.first < *b.first; });
      h.tag('{');
      for (const auto& [key, member] : members) {
        h.text(*key);
        fingerprint_into(*member, h);
      }
      h.tag('}');
      return;
    }
    case nlohmann::json::value_t::array:
      h.tag('[');
      for (const auto& item : value) fingerprint_into(item, h);
      h.tag(']');
      return;
    case nlohmann::json::value_t::string:
      h.tag('s');
      h.text(value.template get_ref<const std::string&>());
      return;
    case nlohmann::json::value_t::boolean:
      h.tag(value.template get<bool>() ? 't' : 'f');
      return;
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float: {
      h.tag('n');
      const double v = value.template get<double>();
      const std::uint64_t bits = std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v);
      h.bytes(&bits, sizeof bits);
      return;
    }
    default:
      h.tag('0');  // null, and what a model never holds
      return;
  }
}

template <typename Json>
std::string fingerprint_of(const Json& value) {
  Fnv1a64 h;
  fingerprint_into(value, h);
  return h.hex();
}

// A key only one method's state holds: a state under another method's name is refused.
struct StateSignature {
  InterpolationMethod method;
  const char* key;
};
constexpr StateSignature kStateSignatures[] = {
    {InterpolationMethod::kKriging, "kernel"},
    {InterpolationMethod::kRbf, "polynomial_degree"},
    {InterpolationMethod::kJoint, "joint_degrees"},
    {InterpolationMethod::kGrid, "node_fiducial"},
};

void check_state_is_the_methods(const json& state, InterpolationMethod method,
                                const std::string& path, const JsonFields& f) {
  for (const StateSignature& s : kStateSignatures) {
    const bool present = state.contains(s.key);
    if (s.method == method && !present) {
      f.fail(join_path(path, "method"), std::string("says ") + to_string(method) +
                                            " but the saved state lacks '" + s.key +
                                            "', which every " + to_string(method) +
                                            " state holds: not fitted as " + to_string(method));
    }
    if (s.method != method && present) {
      f.fail(join_path(path, "method"), std::string("says ") + to_string(method) +
                                            " but the saved state is " + to_string(s.method) +
                                            "'s (it holds '" + s.key + "')");
    }
  }
}

// Kriging's length scales divide distances: zero, negative or non-finite ones are refused here,
// naming the key, rather than where the model is first evaluated.
void check_kriging_state(const json& state, const std::string& path, const JsonFields& f) {
  for (const char* axis : {"x", "y", "z"}) {
    const std::string key = std::string(axis) + ".length_m";
    if (!state.contains(key)) continue;  // restore names a missing key
    const json& value = state.at(key);
    const std::string at = join_path(path, key);
    std::vector<double> values;
    if (value.is_object() && value.contains("values")) {
      values = f.numbers(value, at, "values", -1);
    } else if (value.is_number()) {
      values = {value.get<double>()};
    }
    for (const double v : values) {
      if (!(std::isfinite(v) && v > 0.0)) {
        f.fail(at, "a length scale must be a positive number, found " + std::to_string(v));
      }
    }
  }
}

void check_fitted_from(const json& item, const std::string& path, const SavedCorrector& saved,
                       const JsonFields& f, const std::string& fiducials_fingerprint) {
  if (!item.contains("fitted_from")) return;  // written before models carried it
  const std::string at = join_path(path, "fitted_from");
  const json& from = item.at("fitted_from");
  f.require_object(from, at);
  const std::string method = f.string(from, at, "method");
  if (method != to_string(saved.method)) {
    f.fail(join_path(path, "method"), std::string("says ") + to_string(saved.method) +
                                          " but the corrector was fitted as " + method);
  }
  if (f.string(from, at, "fiducials_fnv1a64") != fiducials_fingerprint) {
    f.fail("fiducials", "changed since the corrector was fitted on them (" +
                            join_path(at, "fiducials_fnv1a64") + " differs): register again");
  }
  if (f.string(from, at, "state_fnv1a64") != fingerprint_of(item.at("state"))) {
    f.fail(join_path(path, "state"), "changed since it was fitted (" +
                                         join_path(at, "state_fnv1a64") +
                                         " differs): register again");
  }
}

}  // namespace

std::string json_fingerprint(const nlohmann::json& value) { return fingerprint_of(value); }
std::string json_fingerprint(const nlohmann::ordered_json& value) { return fingerprint_of(value); }

ojson corrector_json(const SavedCorrector& saved, const std::string& fiducials_fingerprint) {
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
  if (saved.guard) out["guard"] = guard_json(*saved.guard);
  // A term that did not enter changes no correction: kept out, so the file is what it was.
  if (saved.lost_motion && saved.lost_motion->applied)
    out["lost_motion"] = lost_motion_json(*saved.lost_motion);
  out["state"] = state_json(saved.state);
  // What was fitted is checked when read back; a method that keeps no state (octuplet,
  // scattered, trilinear) is rebuilt from the fiducials themselves.
  if (!saved.state.arrays().empty() || !saved.state.texts().empty()) {
    out["fitted_from"] = {{"method", to_string(saved.method)},
                          {"fiducials_fnv1a64", fiducials_fingerprint},
                          {"state_fnv1a64", fingerprint_of(out["state"])}};
  }
  return out;
}

SavedCorrector read_corrector(const json& item, const std::string& path, const JsonFields& f,
                              const std::string& fiducials_fingerprint) {
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
  if (item.contains("guard")) out.guard = read_guard(item.at("guard"), join_path(path, "guard"), f);
  if (item.contains("lost_motion")) {
    out.lost_motion =
        read_lost_motion(item.at("lost_motion"), join_path(path, "lost_motion"), f);
  }
  const json& state = f.member(item, path, "state");
  out.state = read_state(state, join_path(path, "state"), to_string(out.method), f);
  check_state_is_the_methods(state, out.method, path, f);
  check_kriging_state(state, join_path(path, "state"), f);
  check_fitted_from(item, path, out, f, fiducials_fingerprint);
  return out;
}

nlohmann::ordered_json orientation_corrector_json(const SavedOrientationCorrector& saved,
                                                  const std::string& fiducials_fingerprint) {
  nlohmann::ordered_json out;
  out["method"] = to_string(saved.method);
  nlohmann::ordered_json mean = nlohmann::ordered_json::array();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) mean.push_back(finite(saved.mean_residual(r, c), "mean residual"));
  out["mean_residual"] = std::move(mean);
  out["joint_rms_rad"] = finite(saved.joint_rms_rad, "joint rms");
  out["applied"] = saved.applied;
  out["uncorrected_rms_rad"] = finite(saved.uncorrected_rms_rad, "uncorrected rms");
  out["cv_rms_rad"] = finite(saved.cv_rms_rad, "cross-validated rms");
  nlohmann::ordered_json table = nlohmann::ordered_json::array();
  for (const OrientationCvRow& row : saved.cross_validation) {
    table.push_back({{"method", to_string(row.method)},
                     {"applicable", row.applicable},
                     {"note", row.note},
                     {"rms_rad", finite(row.rms_rad, "cross-validated rms")},
                     {"n_predicted", row.n_predicted}});
  }
  out["cross_validation"] = std::move(table);
  if (saved.method == InterpolationMethod::kJoint || saved.joint_terms.degree >= 0 ||
      saved.joint_terms.link_rotations_rad.size() > 0) {
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
    out["joint_terms"]["position_rotation"] = to_string(t.position_rotation);
    out["joint_terms"]["constant_rad"] = {finite(t.constant_rad.x(), "joint terms"),
                                          finite(t.constant_rad.y(), "joint terms"),
                                          finite(t.constant_rad.z(), "joint terms")};
    if (t.position_joint_scales.size() > 0) {
      out["joint_terms"]["position_joint_scales"] = list(t.position_joint_scales);
    }
    if (!t.periodic.empty()) {  // 0-based joints (DH rows), frequencies, then (s, c) per term
      Eigen::VectorXd joints(std::ssize(t.periodic)), omegas(std::ssize(t.periodic));
      for (std::size_t m = 0; m < t.periodic.size(); ++m) {
        joints(static_cast<Eigen::Index>(m)) = t.periodic[m].joint;
        omegas(static_cast<Eigen::Index>(m)) = t.periodic[m].omega_per_rad;
      }
      out["joint_terms"]["periodic_joints"] = list(joints);
      out["joint_terms"]["periodic_omega_per_rad"] = list(omegas);
      out["joint_terms"]["periodic_coefficients"] = list(t.periodic_coefficients);
    }
    out["joint_terms"]["columns"] = t.columns;
    out["joint_terms"]["rank"] = t.rank;
  }
  if (saved.tangent) out["tangent"] = corrector_json(*saved.tangent, fiducials_fingerprint);
  return out;
}

SavedOrientationCorrector read_orientation_corrector(const json& item, const std::string& path,
                                                     const JsonFields& f,
                                                     const std::string& fiducials_fingerprint) {
  f.require_object(item, path);
  SavedOrientationCorrector out;
  out.method = read_method(item, path, "method", f);
  const std::vector<double> mean = f.numbers(item, path, "mean_residual", 9);  // row-major
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.mean_residual(r, c) = mean[static_cast<std::size_t>(3 * r + c)];
  out.joint_rms_rad = f.number(item, path, "joint_rms_rad");
  if (out.joint_rms_rad < 0.0) f.fail(join_path(path, "joint_rms_rad"), "negative");
  // Files written before the orientations' own cross-validation: applied, figures not known.
  const auto flag = [&](const json& object, const std::string& at, const char* key) {
    const json& v = f.member(object, at, key);
    if (!v.is_boolean()) f.fail(join_path(at, key), "expected true or false");
    return v.get<bool>();
  };
  if (item.contains("applied")) out.applied = flag(item, path, "applied");
  for (const auto& [key, value] : {std::pair{"uncorrected_rms_rad", &out.uncorrected_rms_rad},
                                   std::pair{"cv_rms_rad", &out.cv_rms_rad}}) {
    if (!item.contains(key)) continue;
    *value = f.number(item, path, key);
    if (*value < 0.0) f.fail(join_path(path, key), "negative");
  }
  if (item.contains("cross_validation")) {
    const std::string at = join_path(path, "cross_validation");
    const json& rows = item.at("cross_validation");
    if (!rows.is_array() || rows.size() > 16) f.fail(at, "expected an array of at most 16 rows");
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const std::string row_at = at + "[" + std::to_string(i) + "]";
      f.require_object(rows[i], row_at);
      OrientationCvRow row;
      row.method = read_method(rows[i], row_at, "method", f);
      row.applicable = flag(rows[i], row_at, "applicable");
      row.note = f.string(rows[i], row_at, "note");
      row.rms_rad = f.number(rows[i], row_at, "rms_rad");
      if (row.rms_rad < 0.0) f.fail(join_path(row_at, "rms_rad"), "negative");
      row.n_predicted = f.integer(rows[i], row_at, "n_predicted");
      if (row.n_predicted < 0) f.fail(join_path(row_at, "n_predicted"), "negative");
      out.cross_validation.push_back(std::move(row));
    }
  }
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
    if (t.contains("constant_rad")) {
      const std::vector<double> c = f.numbers(t, at, "constant_rad", 3);
      out.joint_terms.constant_rad = Eigen::Vector3d(c[0], c[1], c[2]);
    }
    if (t.contains("position_joint_scales")) {
      out.joint_terms.position_joint_scales = vector("position_joint_scales");
    }
    if (t.contains("periodic_joints")) {  // files written before them: none
      const Eigen::VectorXd joints = vector("periodic_joints");
      const Eigen::VectorXd omegas = vector("periodic_omega_per_rad");
      if (omegas.size() != joints.size()) {
        f.fail(join_path(at, "periodic_omega_per_rad"), "expected one per periodic joint");
      }
      for (Eigen::Index m = 0; m < joints.size(); ++m) {
        if (joints(m) != std::floor(joints(m)) || joints(m) < 0 || joints(m) > 64) {
          f.fail(join_path(at, "periodic_joints"), "expected joint indices 0-64");
        }
        out.joint_terms.periodic.push_back({static_cast<int>(joints(m)), omegas(m)});
      }
      out.joint_terms.periodic_coefficients = vector("periodic_coefficients");
    }
    if (t.contains("position_rotation")) {  // older files: the whole rotation
      try {
        out.joint_terms.position_rotation =
            parse_position_rotation(f.string(t, at, "position_rotation"));
      } catch (const InputError& e) {
        f.fail(join_path(at, "position_rotation"), e.what());
      }
    }
    for (const auto& [key, value] : {std::pair{"columns", &out.joint_terms.columns},
                                     std::pair{"rank", &out.joint_terms.rank}}) {
      if (!t.contains(key)) continue;
      *value = f.integer(t, at, key);
      if (*value < 0 || *value > 10000) f.fail(join_path(at, key), "out of range");
    }
  }
  if (item.contains("tangent")) {
    out.tangent =
        read_corrector(item.at("tangent"), join_path(path, "tangent"), f, fiducials_fingerprint);
  } else if (out.method != InterpolationMethod::kJoint) {
    f.fail(join_path(path, "tangent"), "missing (every method but joint has one)");
  }
  return out;
}

}  // namespace vrreg::io::detail
