// SPDX-License-Identifier: Apache-2.0
#pragma once
// Radial basis function interpolation of a 3-vector field with a polynomial term and a
// smoothing parameter chosen per axis by leave-one-out cross-validation
// (docs/field-models.md).
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/correction_values.hpp"
#include "vrreg/correction/field_prediction.hpp"
#include "vrreg/correction/method_state.hpp"

namespace vrreg {

struct RbfOptions {
  /// Polynomial degree 1 or 2 (4 or 10 terms). The cubic kernel r^3 needs at least degree 1.
  int polynomial_degree = 1;
  /// Up to this many fiducials one global model (smoothing from its exact LOO); above it the
  /// smoothing is chosen on the `smoothing_block` fiducials nearest the centroid and each query is
  /// predicted from its `local_neighbours` nearest fiducials.
  Eigen::Index exact_limit = 1500;
  Eigen::Index local_neighbours = 150;
  /// Above exact_limit, the smoothing is chosen on this many fiducials nearest the centroid
  /// (0: exact_limit). Its eigendecomposition is O(n^3).
  Eigen::Index smoothing_block = 0;
  /// Smoothing values tried: lambda = scale * 10^k for k on a grid from min to max exponent,
  /// scale the mean eigenvalue of the kernel matrix on the polynomial's null space.
  double min_log10_smoothing = -9.0;
  double max_log10_smoothing = 1.0;
  int n_smoothing = 31;
  /// Given smoothing per axis (kernel units, m^3, each finite and >= 0) instead of the
  /// leave-one-out choice: e.g. a refit on most of the same fiducials keeps its parent's. A
  /// local model then reports no LOO RMS (NaN).
  std::optional<Eigen::Vector3d> smoothing{};
};

/// A fitted cubic (r^3) RBF model with polynomial term, per axis.
class RbfModel {
 public:
  /// positions_m: 3 x J nominal robot positions [m]; values_m: 3 x J values [m]. Throws
  /// InputError for too few fiducials (J < polynomial terms + 1), non-finite input, coincident
  /// positions, positions that do not determine the polynomial, or bad options.
  static RbfModel fit(const ConstPoints3Ref& positions_m, const ConstPoints3Ref& values_m,
                      const RbfOptions& options = {});
  /// The model save() wrote, on the same positions and values, without fitting: its weights and
  /// smoothing as saved, so the same predictions bit for bit. Throws InputError when the state
  /// does not fit the data.
  static RbfModel restore(const ConstPoints3Ref& positions_m, const ConstPoints3Ref& values_m,
                          const MethodState& state);
  /// Writes options, frame, smoothing, LOO RMS and (global models) weights into `state`.
  void save(MethodState& state) const;

  ~RbfModel();
  RbfModel(RbfModel&&) noexcept;
  RbfModel& operator=(RbfModel&&) noexcept;

  /// Mean prediction at query_m (3 x N, [m]); sd_m is each axis' LOO RMS (the same for all
  /// queries: the method's own estimate of its error at a new point, noise included).
  [[nodiscard]] FieldPrediction predict(const ConstPoints3Ref& query_m) const;
  /// Leave-one-out RMS per axis at the chosen smoothing [m].
  [[nodiscard]] Eigen::Vector3d cv_rms_m() const;
  /// Chosen smoothing lambda per axis (kernel units, m^3).
  [[nodiscard]] Eigen::Vector3d smoothing() const;
  [[nodiscard]] bool exact() const;
  /// Its leave-one-out RMS in `values`' unit.
  [[nodiscard]] std::string describe(CorrectionValues values = CorrectionValues::kLengthM) const;

 private:
  struct Impl;
  explicit RbfModel(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_{};
};

}  // namespace vrreg
