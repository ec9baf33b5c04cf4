// SPDX-License-Identifier: Apache-2.0
#pragma once
// A model the service answers with: read from its file once, its corrector prepared, and named
// by the SHA-256 of the file's bytes so that every answer can be traced to the file it came from.
#include <limits>
#include <memory>
#include <string>

#include "request.hpp"
#include "vrreg/pipeline/prepared_corrector.hpp"

namespace vrreg::serve {

/// Identity and provenance of a served model (the health endpoint, the audit log).
struct ModelIdentity {
  std::string name;            ///< as clients ask for it
  std::string path;            ///< the file it was read from
  std::string sha256;          ///< of the file's bytes, hex
  std::string file_time_utc;   ///< the file's modification time (when it was fitted and written)
  std::string loaded_at_utc;   ///< when the service loaded it
  std::string method;          ///< the correction method that answers
  std::size_t n_fiducials = 0;
  bool predicts_sd = false;
  bool corrects_orientation = false;  ///< requests may carry the marker's orientation
};

/// A loaded model: immutable, shared between the threads that answer with it.
class ServedModel {
 public:
  ServedModel(ModelIdentity identity, PreparedCorrector corrector);

  /// Corrects one point (paper Eq. 7, 8 and {R, tau}) exactly as `vrreg correct` would.
  /// An extrapolated answer for a point farther from the fiducials' bounding box (sensor frame)
  /// than `max_extrapolation` times the box's diagonal is refused with kTooFar instead.
  /// Never throws: a refusal is a PointAnswer with its code and reason.
  [[nodiscard]] PointAnswer answer(
      const PointRequest& request,
      double max_extrapolation = std::numeric_limits<double>::infinity()) const;

  /// The fiducials' bounding box, sensor frame [mm].
  [[nodiscard]] const Eigen::Vector3d& box_min_mm() const { return box_min_mm_; }
  [[nodiscard]] const Eigen::Vector3d& box_max_mm() const { return box_max_mm_; }

  [[nodiscard]] const ModelIdentity& identity() const { return identity_; }
  [[nodiscard]] const PreparedCorrector& corrector() const { return corrector_; }

 private:
  ModelIdentity identity_;
  PreparedCorrector corrector_;
  Eigen::Vector3d box_min_mm_;
  Eigen::Vector3d box_max_mm_;
};

/// Reads `path`, prepares its corrector (the model's stored one when it answers) and checks that
/// it corrects one of its own fiducials to a finite point. Throws FileError naming the file.
std::shared_ptr<const ServedModel> load_served_model(const std::string& name,
                                                     const std::string& path);

/// SHA-256 of `bytes` as 64 lowercase hex digits (OpenSSL).
std::string sha256_hex(const std::string& bytes);

/// `time` (seconds since the epoch, with fraction) as "2026-11-26T05:30:01.123456Z".
std::string utc_timestamp(double seconds_since_epoch);

/// The current time as utc_timestamp.
std::string utc_now();

}  // namespace vrreg::serve
