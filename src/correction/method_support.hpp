// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to correction: what the correction methods share (method_*.cpp).
#include <memory>
#include <optional>
#include <string>

#include "vrreg/correction/correction_method.hpp"
#include "vrreg/correction/cross_validation.hpp"

namespace vrreg::detail {

/// Predicts every fiducial of `held_out` with `fitted`, in the method's blocks (corrections,
/// stencils and, when the method has one, its own sd): cross-validation's folds and the
/// lost-motion stage's (cross_validation.cpp).
MethodPredictions predict_held_out(const FittedMethod& fitted, const CorrectorData& held_out);

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

/// The edge of the fiducials' box's volume per fiducial [m] (over the axes the box spans; 0 when
/// it spans none).
double volume_spacing_m(const ConstPoints3Ref& points_m);

/// The typical distance between neighbouring fiducials [m]: the larger of the median
/// nearest-neighbour distance and the edge of the layout's volume per fiducial.
double layout_spacing_m(const ConstPoints3Ref& points_m);

/// Where a model of the whole field answers: the box of the fiducials' nominal positions (the
/// field is known there; beyond it a model would extrapolate), `margin_m` beyond its faces.
struct SupportBox {
  Eigen::Vector3d lo_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d hi_m = Eigen::Vector3d::Zero();
  double margin_m = 0.0;
  [[nodiscard]] bool contains(const Eigen::Vector3d& p_m) const {
    return (p_m.array() >= lo_m.array() - margin_m).all() &&
           (p_m.array() <= hi_m.array() + margin_m).all();
  }
  /// FittedMethod::clamp_to_support for a box: each point to its nearest point of the box.
  [[nodiscard]] Eigen::VectorXd clamp(Points3& points_m) const {
    return clamp_to_box(points_m, lo_m.array() - margin_m, hi_m.array() + margin_m);
  }
  static Eigen::VectorXd clamp_to_box(Points3& points_m, const Eigen::Vector3d& lo_m,
                                      const Eigen::Vector3d& hi_m) {
    Eigen::VectorXd moved_m(points_m.cols());
    for (Eigen::Index i = 0; i < points_m.cols(); ++i) {
      const Eigen::Vector3d p = points_m.col(i);
      points_m.col(i) = p.cwiseMax(lo_m).cwiseMin(hi_m);
      moved_m(i) = (points_m.col(i) - p).norm();
    }
    return moved_m;
  }
};

/// Marks entries [begin, end) of `out` ok where `support` holds the point's registered position
/// (or the query asks beyond it), else `outside support` with no correction.
inline void flag_outside_support(const SupportBox& support, const MethodQuery& query,
                                 Eigen::Index begin, Eigen::Index end, MethodPredictions& out) {
  for (Eigen::Index i = begin; i < end; ++i) {
    if (query.beyond_support || support.contains(query.registered_robot_m.col(i))) {
      out.stencils[static_cast<std::size_t>(i)] = Stencil{};
    } else {
      out.stencils[static_cast<std::size_t>(i)] = flagged_stencil(StencilStatus::kOutsideSupport);
      out.corrections_sensor_m.col(i).setZero();
    }
  }
}

/// The support of a field model fitted on `fiducials_robot_m`: their box and a margin of a
/// quarter of the layout spacing. A fiducial on the layout's face registers off its nominal
/// position by the robot's error (up to ~1 mm) and must still be corrected, while a quarter
/// spacing is where a smooth model's extrapolation is still bounded by its neighbours (on the
/// test cells the error there is within the sd; half a spacing out it doubles).
SupportBox field_support(const ConstPoints3Ref& fiducials_robot_m);

/// Fewest fiducials a model of the whole field is fitted on.
inline constexpr Eigen::Index kMinFieldModelFiducials = 12;

// A large cell (vrreg/correction/cross_validation.hpp: over kLargeCellFiducials) also corrects
// with kriging's and rbf's local models instead of a table: a table node costs a local solve, and
// the table has ~15 nodes per fiducial.

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
