// SPDX-License-Identifier: Apache-2.0
// Barycentric RRBC weights in the Delaunay tetrahedron holding the registered target (Eq. 7) as a
// correction method. The tetrahedralization is not saved but rebuilt on restore: qhull is
// deterministic (the same stencils), fast at cell sizes, and the tetrahedra would outweigh the
// rest of the model file several times.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "method_support.hpp"
#include "point_index.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/correction/scattered.hpp"

namespace vrreg::detail {
namespace {

class ScatteredMethod final : public FittedMethod {
 public:
  ScatteredMethod(const CorrectorData& data, const MethodSettings& settings)
      : stencils_(data.fiducials_robot_m, settings.match_tolerance_m),
        corrections_sensor_m_(data.corrections_sensor_m) {}

  [[nodiscard]] InterpolationMethod method() const override {
    return InterpolationMethod::kScattered;
  }
  [[nodiscard]] std::string describe() const override { return stencils_.describe(); }

  void predict(const MethodQuery& query, Eigen::Index begin, Eigen::Index end,
               MethodPredictions& out) const override {
    for (Eigen::Index i = begin; i < end; ++i) {
      Stencil& stencil = out.stencils[static_cast<std::size_t>(i)];
      stencil = stencils_.stencil(query.registered_robot_m.col(i));
      if (stencil.status == StencilStatus::kOk) {
        out.corrections_sensor_m.col(i) = interpolate_correction(stencil, corrections_sensor_m_);
      } else {
        out.corrections_sensor_m.col(i).setZero();
      }
    }
  }

  [[nodiscard]] MethodState save() const override { return MethodState("scattered"); }

 private:
  ScatteredStencils stencils_;
  Points3 corrections_sensor_m_;
};

// What qhull would refuse, said before it is asked: too few fiducials, two at one position,
// all in a plane.
std::string scattered_unavailable(const CorrectorData& data, const MethodSettings& settings) {
  const Eigen::Index n = data.size();
  if (n < 4) {
    return "scattered interpolation needs at least 4 fiducials, got " + std::to_string(n);
  }
  const PointIndex index(data.fiducials_robot_m);
  if (const auto pair = index.duplicate(settings.match_tolerance_m)) {
    return "fiducials " + std::to_string(pair->first) + " and " + std::to_string(pair->second) +
           " share a nominal robot position (within " +
           std::to_string(units::m_to_mm(settings.match_tolerance_m)) +
           " mm): use one arm configuration per model";
  }
  const Points3 centred =
      data.fiducials_robot_m.colwise() - data.fiducials_robot_m.rowwise().mean();
  // The RMS distance from the best-fitting plane: within the tolerance, the layout is flat.
  const Eigen::Vector3d variance_m2 =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(centred * centred.transpose() /
                                                     static_cast<double>(n))
          .eigenvalues();
  const double thickness_m = std::sqrt(std::max(variance_m2(0), 0.0));
  if (thickness_m <= settings.match_tolerance_m ||
      thickness_m <= 1e-9 * std::sqrt(variance_m2(2))) {
    return "the fiducials lie in a plane (or on a line): no tetrahedra to interpolate in";
  }
  return {};
}

FitOutcome fit_scattered(const CorrectorData& data, const MethodSettings& settings) {
  return fitted<ScatteredMethod>(data, settings);
}

std::unique_ptr<const FittedMethod> restore_scattered(const MethodState&,
                                                      const CorrectorData& data,
                                                      const MethodSettings& settings) {
  return std::make_unique<const ScatteredMethod>(data, settings);
}

}  // namespace

CorrectionMethod scattered_method() {
  return {InterpolationMethod::kScattered, false, scattered_unavailable, fit_scattered,
          restore_scattered};
}

}  // namespace vrreg::detail
