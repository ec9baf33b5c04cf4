#pragma once
// Internal to correction: what the correction methods share (method_*.cpp).
#include <memory>
#include <optional>
#include <string>

#include "vrreg/correction/correction_method.hpp"

namespace vrreg::detail {

/// A stencil that says only why there is no prediction.
inline Stencil flagged_stencil(StencilStatus status) {
  Stencil s;
  s.status = status;
  return s;
}

/// Fills entries [begin, end) of `out` one point at a time: `at(i)` gives point i's correction,
/// or nullopt where the method has none (status `missing`, correction 0).
template <class At>
void predict_pointwise(Eigen::Index begin, Eigen::Index end, MethodPredictions& out,
                       StencilStatus missing, At at) {
  for (Eigen::Index i = begin; i < end; ++i) {
    const std::optional<Eigen::Vector3d> c = at(i);
    Stencil& s = out.stencils[static_cast<std::size_t>(i)];
    if (c) {
      s = Stencil{};
      out.corrections_sensor_m.col(i) = *c;
    } else {
      s = flagged_stencil(missing);
      out.corrections_sensor_m.col(i).setZero();
    }
  }
}

/// A fitted method as a fit outcome.
template <class Method, class... Args>
FitOutcome fitted(Args&&... args) {
  return FitOutcome{std::make_unique<const Method>(std::forward<Args>(args)...), {}};
}

inline FitOutcome not_applicable(std::string why) { return FitOutcome{nullptr, std::move(why)}; }

// One factory set per method, each in its own file (method_*.cpp), listed in method_registry.cpp.
CorrectionMethod grid_method();
CorrectionMethod scattered_method();
CorrectionMethod octuplet_method();
CorrectionMethod trilinear_method();
CorrectionMethod kriging_method();
CorrectionMethod rbf_method();
CorrectionMethod joint_method();

/// Fewest fiducials a model of the whole field is fitted on.
inline constexpr Eigen::Index kMinFieldModelFiducials = 12;

/// Why a field model that predicts from positions alone cannot be used: two fiducials at one
/// nominal position in different arm configurations (a field of position cannot tell them apart);
/// empty when none.
std::string configuration_clash(const CorrectorData& data, double tolerance_m);

/// Why a polynomial of `degree` (a trend, an RBF's polynomial part) cannot be fitted to the
/// fiducials' nominal positions (too few, coplanar or collinear), or empty; `what` names the model.
std::string polynomial_unavailable(const CorrectorData& data, int degree, const char* what);

/// Why an interpolating model cannot pass through the fiducials: two at one nominal position
/// (within 1e-9 of the layout's extent), or empty.
std::string coincidence_unavailable(const CorrectorData& data, const char* what);

}  // namespace vrreg::detail
