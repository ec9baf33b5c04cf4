// SPDX-License-Identifier: Apache-2.0
// The paper's octuplet (dataset B, Eq. 7 with weights 1/8): the fiducials at the 8 corners of the
// cube of edge a around the target's nominal robot position, as a correction method. With
// Procedure 2's Strategy 3 each corner is taken in the arm configuration nearest the target's
// (method_nearest_configuration.cpp).
#include <algorithm>

#include "method_support.hpp"
#include "point_index.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/correction/octuplet.hpp"

namespace vrreg::detail {

FitOutcome fit_nearest_configuration(const CorrectorData& data, const MethodSettings& settings);
std::unique_ptr<const FittedMethod> restore_nearest_configuration(const CorrectorData& data,
                                                                  const MethodSettings& settings);

namespace {

// Where each fiducial was read, when every one of them came from a file line: then a corner
// measured more than once takes the reading nearest the target's in the visiting order.
std::vector<std::size_t> usable_sequence(const CorrectorData& data) {
  const bool all = !data.sequence.empty() &&
                   std::all_of(data.sequence.begin(), data.sequence.end(),
                               [](std::size_t line) { return line > 0; });
  return all ? data.sequence : std::vector<std::size_t>{};
}

class OctupletMethod final : public FittedMethod {
 public:
  OctupletMethod(const CorrectorData& data, const MethodSettings& settings)
      : stencils_(data.fiducials_robot_m, settings.cube_edge_m, settings.match_tolerance_m,
                  usable_sequence(data)),
        corrections_sensor_m_(data.corrections_sensor_m),
        sequenced_(!usable_sequence(data).empty()) {
    if (!sequenced_) return;  // without a sequence the constructor refused shared positions
    const PointIndex index(data.fiducials_robot_m);
    if (const auto pair = index.duplicate(settings.match_tolerance_m)) {
      shared_ = "fiducials " + std::to_string(pair->first) + " and " +
                std::to_string(pair->second) + " share a nominal robot position (within " +
                std::to_string(units::m_to_mm(settings.match_tolerance_m)) +
                " mm): use one arm configuration per model";
    }
  }

  [[nodiscard]] InterpolationMethod method() const override {
    return InterpolationMethod::kOctuplet;
  }
  [[nodiscard]] std::string describe() const override { return stencils_.describe(); }
  [[nodiscard]] MethodNeeds needs() const override { return {.nominal_robot = true}; }

  // A corner measured twice is chosen by the visiting order: points without one cannot choose.
  void check_query(const MethodQuery& query) const override {
    VRREG_THROW_UNLESS(!query.sequence.empty() || shared_.empty(), shared_);
  }

  void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
               MethodPredictions& out) const override {
    for (Eigen::Index i = begin; i < end; ++i) {
      Stencil& stencil = out.stencils[static_cast<std::size_t>(i)];
      stencil = stencils_.stencil(
          query.robot_nominal_m.col(i),
          query.sequence.empty() ? 0 : query.sequence[static_cast<std::size_t>(i)]);
      if (stencil.status == StencilStatus::kOk) {
        out.corrections_sensor_m.col(i) = interpolate_correction(stencil, corrections_sensor_m_);
      } else {
        out.corrections_sensor_m.col(i).setZero();
      }
    }
  }

  [[nodiscard]] MethodState save() const override { return MethodState("octuplet"); }

 private:
  OctupletStencils stencils_;
  Points3 corrections_sensor_m_;
  bool sequenced_ = false;
  std::string shared_;  ///< why points without a sequence cannot be corrected, or empty
};

std::string octuplet_unavailable(const CorrectorData& data, const MethodSettings& settings) {
  if (settings.nearest_configuration) return {};  // Strategy 3 checks its own
  if (!(settings.cube_edge_m > 0.0)) {
    return "octuplet interpolation needs a cube edge (`cube_edge`)";
  }
  if (data.size() < 8) {
    return "octuplet interpolation needs at least 8 fiducials, got " + std::to_string(data.size());
  }
  return {};
}

FitOutcome fit_octuplet(const CorrectorData& data, const MethodSettings& settings) {
  if (settings.nearest_configuration) return fit_nearest_configuration(data, settings);
  return fitted<OctupletMethod>(data, settings);
}

std::unique_ptr<const FittedMethod> restore_octuplet(const MethodState&, const CorrectorData& data,
                                                     const MethodSettings& settings) {
  if (settings.nearest_configuration) return restore_nearest_configuration(data, settings);
  return std::make_unique<const OctupletMethod>(data, settings);
}

}  // namespace

CorrectionMethod octuplet_method() {
  return {InterpolationMethod::kOctuplet, false, octuplet_unavailable, fit_octuplet,
          restore_octuplet};
}

}  // namespace vrreg::detail
