// SPDX-License-Identifier: Apache-2.0
#include "served_model.hpp"

#include <fmt/format.h>
#include <openssl/evp.h>
#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <utility>

#include "vrreg/core/file_error.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/input_file.hpp"
#include "vrreg/io/model_json.hpp"

namespace vrreg::serve {
namespace {

Eigen::Vector3d mm_of(const Points3& points_m) {
  Eigen::Vector3d v;
  for (int a = 0; a < 3; ++a) v(a) = units::m_to_mm(points_m(a, 0));
  return v;
}

}  // namespace

std::string sha256_hex(const std::string& bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr) != 1) {
    throw std::runtime_error("SHA-256 failed (OpenSSL)");
  }
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) hex += fmt::format("{:02x}", digest[i]);
  return hex;
}

std::string utc_timestamp(double seconds_since_epoch) {
  const auto whole = static_cast<std::time_t>(std::floor(seconds_since_epoch));
  const auto micros = static_cast<long>(std::floor((seconds_since_epoch - double(whole)) * 1e6));
  std::tm tm{};
  gmtime_r(&whole, &tm);
  return fmt::format("{:04}-{:02}-{:02}T{:02}:{:02}:{:02}.{:06}Z", tm.tm_year + 1900, tm.tm_mon + 1,
                     tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, micros);
}

std::string utc_now() {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return utc_timestamp(std::chrono::duration<double>(now).count());
}

ServedModel::ServedModel(ModelIdentity identity, PreparedCorrector corrector)
    : identity_(std::move(identity)),
      corrector_(std::move(corrector)),
      box_min_mm_(Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity())),
      box_max_mm_(-box_min_mm_) {
  for (const auto& f : corrector_.model().fiducials) {
    for (int a = 0; a < 3; ++a) {
      const double v = units::m_to_mm(f.sensor_m(a));
      box_min_mm_(a) = std::min(box_min_mm_(a), v);
      box_max_mm_(a) = std::max(box_max_mm_(a), v);
    }
  }
}

PointAnswer ServedModel::answer(const PointRequest& request, double max_extrapolation) const {
  try {
    MeasuredPoints points;
    points.sensor_m.resize(3, 1);
    // As the measurement CSV reader converts: dividing by 1000 rounds correctly.
    for (int a = 0; a < 3; ++a) points.sensor_m(a, 0) = request.sensor_mm(a) / units::kMillimetresPerMetre;
    if (request.config) points.configs.push_back(*request.config);
    const int needed = corrector_.joints_needed();
    if (needed > 0 && static_cast<int>(request.joints_rad.size()) != needed) {
      return PointAnswer::refusal(
          ReplyCode::kInput,
          fmt::format("model '{}' ({}) needs the {} commanded joints of the point (joints ...), "
                      "{} given",
                      identity_.name, identity_.method, needed, request.joints_rad.size()));
    }
    if (!request.joints_rad.empty()) {
      points.joints_rad = Eigen::Map<const Eigen::VectorXd>(
          request.joints_rad.data(), static_cast<Eigen::Index>(request.joints_rad.size()));
    }
    if (!request.approach_sign.empty()) {
      points.approach_sign = Eigen::Map<const Eigen::VectorXd>(
          request.approach_sign.data(), static_cast<Eigen::Index>(request.approach_sign.size()));
    }
    if (request.q_sensor_marker) {
      if (!corrector_.corrects_orientation()) {
        return PointAnswer::refusal(
            ReplyCode::kInput,
            fmt::format("model '{}' corrects positions only (its fiducials carry no "
                        "orientations): send the point without rotvec/quat/abc",
                        identity_.name));
      }
      points.q_sensor_marker.push_back(*request.q_sensor_marker);
    }
    const CorrectResult r = corrector_.correct(points, request.extrapolate);
    const TargetCorrection& c = r.correction;
    if (c.stencils.size() != 1) {
      return PointAnswer::refusal(ReplyCode::kInput,
                                  "the model answers no point for this request (configuration "
                                  "label or joints do not match its fiducials)");
    }
    const StencilStatus status = c.stencils.front().status;
    if (status != StencilStatus::kOk && status != StencilStatus::kExtrapolated) {
      PointAnswer refused = PointAnswer::refusal(
          ReplyCode::kNotCorrectable,
          fmt::format("{}: {}{}", identity_.name, to_string(status),
                      status == StencilStatus::kOutsideSupport
                          ? " (add 'extrapolate' to correct field models there anyway)"
                          : ""));
      refused.status = to_string(status);
      refused.uncorrected_robot_mm = mm_of(c.uncorrected_robot_m);
      return refused;
    }
    if (status == StencilStatus::kExtrapolated && std::isfinite(max_extrapolation)) {
      // A field model extrapolates anywhere; a robot sent kilometres away is a typing error or
      // a wrong frame, whatever sd is attached.
      const Eigen::Vector3d outside =
          (box_min_mm_ - request.sensor_mm).cwiseMax(request.sensor_mm - box_max_mm_).cwiseMax(0.0);
      const double diagonal_mm = (box_max_mm_ - box_min_mm_).norm();
      if (!(outside.norm() <= max_extrapolation * diagonal_mm)) {
        PointAnswer refused = PointAnswer::refusal(
            ReplyCode::kTooFar,
            fmt::format("{}: {:.1f} mm outside the fiducials' box, extrapolated at most {:.1f} mm "
                        "({} times its diagonal)",
                        identity_.name, outside.norm(), max_extrapolation * diagonal_mm,
                        max_extrapolation));
        refused.uncorrected_robot_mm = mm_of(c.uncorrected_robot_m);
        return refused;
      }
    }
    PointAnswer a;
    a.status = to_string(status);
    a.robot_mm = mm_of(c.corrected_robot_m);
    a.uncorrected_robot_mm = mm_of(c.uncorrected_robot_m);
    a.sd_mm = c.predicted_sd_m.size() > 0 ? units::m_to_mm(c.predicted_sd_m(0)) : 0.0;
    if (!a.robot_mm.allFinite() || !std::isfinite(a.sd_mm) || a.sd_mm < 0.0) {
      return PointAnswer::refusal(ReplyCode::kInternal, "the correction is not finite");
    }
    if (request.q_sensor_marker) {
      if (!r.orientation || r.orientation->status.size() != 1) {
        return PointAnswer::refusal(ReplyCode::kInternal, "the model answered no orientation");
      }
      const OrientationCorrection& o = *r.orientation;
      const StencilStatus o_status = o.status.front();
      if (o_status != StencilStatus::kOk && o_status != StencilStatus::kExtrapolated) {
        PointAnswer refused = PointAnswer::refusal(
            ReplyCode::kNotCorrectable,
            fmt::format("{}: the orientation: {}", identity_.name, to_string(o_status)));
        refused.status = to_string(o_status);
        refused.uncorrected_robot_mm = a.uncorrected_robot_mm;
        return refused;
      }
      a.q_robot_marker = Eigen::Quaterniond(o.corrected_R_robot_marker.front());
      a.uncorrected_q_robot_marker = Eigen::Quaterniond(o.uncorrected_R_robot_marker.front());
      a.rotation_applied_rad = o.corrections_robot_rad.col(0);
      a.angle_sd_rad = o.predicted_sd_rad.size() > 0 ? o.predicted_sd_rad(0) : 0.0;
      if (!a.q_robot_marker->coeffs().allFinite() || !a.rotation_applied_rad.allFinite() ||
          !std::isfinite(a.angle_sd_rad) || a.angle_sd_rad < 0.0) {
        return PointAnswer::refusal(ReplyCode::kInternal, "the orientation is not finite");
      }
    }
    return a;
  } catch (const InputError& e) {
    return PointAnswer::refusal(ReplyCode::kInput, e.what());
  } catch (const std::exception& e) {
    return PointAnswer::refusal(ReplyCode::kInternal, e.what());
  }
}

std::shared_ptr<const ServedModel> load_served_model(const std::string& name,
                                                     const std::string& path) {
  const std::string text = io::read_input_file(path);
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw FileError(path, 0, "cannot open (removed while read)");
  auto model = std::make_shared<RegistrationModel>(io::parse_model_json(text, path));
  ModelIdentity id;
  id.name = name;
  id.path = path;
  id.sha256 = sha256_hex(text);
  id.file_time_utc = utc_timestamp(double(st.st_mtim.tv_sec) + 1e-9 * double(st.st_mtim.tv_nsec));
  id.loaded_at_utc = utc_now();
  id.n_fiducials = model->fiducials.size();
  try {
    PreparedCorrector corrector(std::move(model), CorrectOptions{});
    id.method = to_string(corrector.method());
    id.predicts_sd = corrector.predicts_sd();
    id.corrects_orientation = corrector.corrects_orientation();
    auto served = std::make_shared<const ServedModel>(std::move(id), std::move(corrector));
    // The check: one of its own fiducials, where every method answers, must come out finite.
    const RegistrationModel& m = served->corrector().model();
    PointRequest probe;
    probe.model = name;
    for (int a = 0; a < 3; ++a) probe.sensor_mm(a) = units::m_to_mm(m.fiducials.front().sensor_m(a));
    probe.joints_rad = m.fiducials.front().q_rad;
    if (m.fiducials.front().config) probe.config = m.fiducials.front().config;
    probe.extrapolate = true;
    if (served->identity()
            .corrects_orientation) {  // the orientation too, as the fiducial's measured one
      probe.q_sensor_marker = m.fiducials.front().q_sensor_marker;
      probe.orientation_form = OrientationForm::kQuaternion;
    }
    const PointAnswer check = served->answer(probe);
    if (check.code == ReplyCode::kInternal) {
      throw FileError(path, 0, "the model does not correct its own fiducial: " + check.reason);
    }
    return served;
  } catch (const FileError&) {
    throw;
  } catch (const InputError& e) {
    throw FileError(path, 0, e.what());
  }
}

}  // namespace vrreg::serve
