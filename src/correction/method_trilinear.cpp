// SPDX-License-Identifier: Apache-2.0
// Trilinear interpolation on the fiducials' finest lattice, its empty nodes filled from their
// neighbours (filled_lattice.hpp), as a correction method of the whole field. Its sd is the
// corrector's cross-validation. Not saved: filling the lattice again is deterministic and quick.
#include "method_support.hpp"
#include "vrreg/correction/filled_lattice.hpp"

namespace vrreg::detail {
namespace {

class TrilinearMethod final : public FittedMethod {
 public:
  TrilinearMethod(FilledLattice lattice, double tolerance_m)
      : lattice_(std::move(lattice)), tolerance_m_(tolerance_m) {}

  [[nodiscard]] InterpolationMethod method() const override {
    return InterpolationMethod::kTrilinear;
  }
  [[nodiscard]] std::string describe() const override {
    return "trilinear, " + lattice_.describe();
  }

  void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
               MethodPredictions& out) const override {
    predict_pointwise(begin, end, out, StencilStatus::kOutsideGrid, [&](Eigen::Index i) {
      return lattice_correction(lattice_, query.registered_robot_m.col(i), tolerance_m_);
    });
  }

  [[nodiscard]] MethodState save() const override { return MethodState("trilinear"); }

 private:
  FilledLattice lattice_;
  double tolerance_m_;
};

FitOutcome fit_trilinear(const CorrectorData& data, const MethodSettings& settings) {
  std::string why;
  std::optional<FilledLattice> lattice = try_fill_lattice(
      data.fiducials_robot_m, data.corrections_sensor_m, settings.match_tolerance_m, why);
  if (!lattice) return not_applicable(why);
  return fitted<TrilinearMethod>(std::move(*lattice), settings.match_tolerance_m);
}

std::unique_ptr<const FittedMethod> restore_trilinear(const MethodState&,
                                                      const CorrectorData& data,
                                                      const MethodSettings& settings) {
  return std::make_unique<const TrilinearMethod>(
      fill_lattice(data.fiducials_robot_m, data.corrections_sensor_m, settings.match_tolerance_m),
      settings.match_tolerance_m);
}

std::string trilinear_unavailable(const CorrectorData& data, const MethodSettings&) {
  if (data.size() < kMinFieldModelFiducials) return "fewer than 12 fiducials";
  return {};
}

}  // namespace

CorrectionMethod trilinear_method() {
  return {InterpolationMethod::kTrilinear, true, trilinear_unavailable, fit_trilinear,
          restore_trilinear};
}

}  // namespace vrreg::detail
