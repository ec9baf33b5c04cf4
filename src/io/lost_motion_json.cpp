// SPDX-License-Identifier: Apache-2.0
#include "lost_motion_json.hpp"

#include <cmath>
#include <cstdint>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::io::detail {
namespace {

using ojson = nlohmann::ordered_json;
using nlohmann::json;

constexpr double kRadPerArcmin = M_PI / (180.0 * 60.0);

}  // namespace

ojson lost_motion_json(const LostMotionTerm& term) {
  const Eigen::Index n = term.play_rad.size();
  VRREG_THROW_UNLESS(term.play_rad.allFinite() && term.covariance_rad2.allFinite() &&
                         term.covariance_rad2.rows() == n && term.covariance_rad2.cols() == n,
                     "model: the lost-motion term has "
                         << n << " plays and a " << term.covariance_rad2.rows() << " x "
                         << term.covariance_rad2.cols() << " covariance, or non-finite values");
  ojson out = ojson::object();
  out["applied"] = term.applied;
  ojson play = ojson::array();
  for (Eigen::Index j = 0; j < n; ++j) play.push_back(term.play_rad(j));
  out["play_rad"] = std::move(play);
  ojson covariance = ojson::array();
  for (Eigen::Index r = 0; r < n; ++r) {
    ojson row = ojson::array();
    for (Eigen::Index c = 0; c < n; ++c) row.push_back(term.covariance_rad2(r, c));
    covariance.push_back(std::move(row));
  }
  out["covariance_rad2"] = std::move(covariance);
  out["cv_rms_with_m"] = term.cv_rms_with_m;
  out["cv_rms_without_m"] = term.cv_rms_without_m;
  out["judged_by"] = to_string(term.judged_by);
  out["n_compared"] = term.n_compared;
  out["reason"] = term.reason;
  return out;
}

json lost_motion_result_json(const LostMotionTerm& term) {
  json out = json::object();
  out["applied"] = term.applied;
  json joints = json::array();
  for (Eigen::Index j = 0; j < term.play_rad.size(); ++j) {
    joints.push_back(
        {{"joint", j + 1},
         {"play_arcmin", term.play_rad(j) / kRadPerArcmin},
         {"sd_arcmin", std::sqrt(std::max(term.covariance_rad2(j, j), 0.0)) / kRadPerArcmin}});
  }
  out["joints"] = std::move(joints);
  out["cv_rms_with_mm"] = units::m_to_mm(term.cv_rms_with_m);
  out["cv_rms_without_mm"] = units::m_to_mm(term.cv_rms_without_m);
  out["judged_by"] = to_string(term.judged_by);
  out["n_compared"] = term.n_compared;
  out["reason"] = term.reason;
  return out;
}

LostMotionTerm read_lost_motion(const json& item, const std::string& path, const JsonFields& f) {
  f.require_object(item, path);
  LostMotionTerm out;
  const json& applied = f.member(item, path, "applied");
  if (!applied.is_boolean()) f.fail(join_path(path, "applied"), "expected true or false");
  out.applied = applied.get<bool>();
  const std::vector<double> play = f.numbers(item, path, "play_rad", -1);
  const auto n = static_cast<Eigen::Index>(play.size());
  if (n == 0) f.fail(join_path(path, "play_rad"), "no joints");
  out.play_rad = Eigen::Map<const Eigen::VectorXd>(play.data(), n);
  const json& covariance = f.member(item, path, "covariance_rad2");
  const std::string covariance_path = join_path(path, "covariance_rad2");
  if (!covariance.is_array() || static_cast<Eigen::Index>(covariance.size()) != n)
    f.fail(covariance_path, "expected " + std::to_string(n) + " rows");
  out.covariance_rad2.resize(n, n);
  for (Eigen::Index r = 0; r < n; ++r) {
    const std::vector<double> row =
        f.array_of_numbers(covariance[static_cast<std::size_t>(r)],
                           covariance_path + "[" + std::to_string(r) + "]", static_cast<int>(n));
    for (Eigen::Index c = 0; c < n; ++c)
      out.covariance_rad2(r, c) = row[static_cast<std::size_t>(c)];
  }
  if (!out.covariance_rad2.isApprox(out.covariance_rad2.transpose()) ||
      (out.covariance_rad2.diagonal().array() < 0.0).any())
    f.fail(covariance_path, "not a covariance (symmetric, variances >= 0)");
  out.cv_rms_with_m = f.number(item, path, "cv_rms_with_m");
  out.cv_rms_without_m = f.number(item, path, "cv_rms_without_m");
  if (out.cv_rms_with_m < 0.0) f.fail(join_path(path, "cv_rms_with_m"), "negative");
  if (out.cv_rms_without_m < 0.0) f.fail(join_path(path, "cv_rms_without_m"), "negative");
  try {
    out.judged_by = parse_interpolation_method(f.string(item, path, "judged_by"));
  } catch (const InputError& e) {
    f.fail(join_path(path, "judged_by"), e.what());
  }
  const json& compared = f.member(item, path, "n_compared");
  if (!compared.is_number_unsigned())
    f.fail(join_path(path, "n_compared"), "expected a whole number >= 0");
  out.n_compared = static_cast<Eigen::Index>(compared.get<std::uint64_t>());
  out.reason = f.string(item, path, "reason");
  return out;
}

}  // namespace vrreg::io::detail
