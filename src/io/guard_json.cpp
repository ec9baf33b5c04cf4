// SPDX-License-Identifier: Apache-2.0
#include "guard_json.hpp"

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::io::detail {
namespace {

using ojson = nlohmann::ordered_json;
using nlohmann::json;

bool read_bool(const json& item, const std::string& path, const std::string& key,
               const JsonFields& f) {
  const json& v = f.member(item, path, key);
  if (!v.is_boolean()) f.fail(join_path(path, key), "expected true or false");
  return v.get<bool>();
}

}  // namespace

ojson guard_json(const CorrectionGuard& guard) {
  ojson out = ojson::object();
  out["judged"] = guard.judged;
  out["applied"] = guard.applied;
  out["judged_by"] = to_string(guard.judged_by);
  out["cv_rms_m"] = guard.cv_rms_m;
  out["uncorrected_rms_m"] = guard.uncorrected_rms_m;
  out["n_judged"] = guard.n_judged;
  out["note"] = guard.note;
  return out;
}

json guard_result_json(const CorrectionGuard& guard) {
  json out = json::object();
  out["judged"] = guard.judged;
  out["applied"] = guard.applied;
  out["judged_by"] = to_string(guard.judged_by);
  out["cv_rms_mm"] = units::m_to_mm(guard.cv_rms_m);
  out["uncorrected_rms_mm"] = units::m_to_mm(guard.uncorrected_rms_m);
  out["n_judged"] = guard.n_judged;
  out["note"] = guard.note;
  return out;
}

CorrectionGuard read_guard(const json& item, const std::string& path, const JsonFields& f) {
  f.require_object(item, path);
  CorrectionGuard out;
  out.judged = read_bool(item, path, "judged", f);
  out.applied = read_bool(item, path, "applied", f);
  try {
    out.judged_by = parse_interpolation_method(f.string(item, path, "judged_by"));
  } catch (const InputError& e) {
    f.fail(join_path(path, "judged_by"), e.what());
  }
  out.cv_rms_m = f.number(item, path, "cv_rms_m");
  out.uncorrected_rms_m = f.number(item, path, "uncorrected_rms_m");
  if (out.cv_rms_m < 0.0) f.fail(join_path(path, "cv_rms_m"), "negative");
  if (out.uncorrected_rms_m < 0.0) f.fail(join_path(path, "uncorrected_rms_m"), "negative");
  const json& n = f.member(item, path, "n_judged");
  if (!n.is_number_unsigned()) f.fail(join_path(path, "n_judged"), "expected a whole number >= 0");
  out.n_judged = static_cast<Eigen::Index>(n.get<std::uint64_t>());
  out.note = f.string(item, path, "note");
  // The decision must follow from the figures: an edited "applied" would serve a correction
  // its own cross-validation found worse than none (or hide one that is better).
  if (out.judged && out.applied != (out.cv_rms_m < out.uncorrected_rms_m ||
                                    out.uncorrected_rms_m == 0.0)) {
    f.fail(join_path(path, "applied"), "does not follow from cv_rms_m and uncorrected_rms_m");
  }
  if (!out.judged && !out.applied) f.fail(join_path(path, "applied"), "false for an unjudged correction");
  return out;
}

}  // namespace vrreg::io::detail
