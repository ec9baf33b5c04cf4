// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to correction: a field model read from its table (field_table.hpp) as a correction
// method, and how the table is built from the exact model.
#include <functional>
#include <optional>
#include <memory>

#include "field_table.hpp"
#include "vrreg/correction/correction_method.hpp"

namespace vrreg::detail {

/// The exact model's correction and sd at `points_m` (registered robot frame), for the table:
/// fills corrections (3 x n) and sd (n, or empty when the model gives none).
using ExactField = std::function<void(const Points3& points_m, Points3& corrections_sensor_m,
                                      Eigen::VectorXd& sd_m)>;

/// Samples `exact` on a lattice over the fiducials' support (field_support; spacing from their layout, refined
/// once when the measured deviation exceeds 1/20 of the fiducials' noise `noise_sd_m`, per axis
/// [m], or 1 um without it) and checks it at seeded points; nullopt when even the refined table
/// deviates by more than 5 times that target (the exact model is kept).
std::optional<FieldTable> build_field_table(const ExactField& exact, const ConstPoints3Ref& fiducials_robot_m,
                             std::optional<double> noise_sd_m);

/// The tabulated form of a fitted method: `exact_state` is the exact method's saved state (kept
/// so that the exact model can be restored), `exact_description` its description; `values` what
/// the field's values are (the unit its description prints the table's deviations in).
std::unique_ptr<const FittedMethod> tabulated_method(FieldTable table, InterpolationMethod method,
                                                     MethodState exact_state,
                                                     std::string exact_description,
                                                     CorrectionValues values);

/// True when `state` is a tabulated method's.
bool is_tabulated(const MethodState& state);

/// A tabulated method's state without its table: the exact method's own.
MethodState exact_state_of(const MethodState& state);

/// The tabulated method saved in `state`.
std::unique_ptr<const FittedMethod> restore_tabulated(const MethodState& state,
                                                      InterpolationMethod method,
                                                      CorrectionValues values);

}  // namespace vrreg::detail
