// SPDX-License-Identifier: Apache-2.0
#pragma once
// Which interpolation evaluate and correct use: the model's stored settings, with what the caller
// chose on top (so it is always clear which wins).
#include <optional>

#include "vrreg/correction/interpolation.hpp"

namespace vrreg {

/// Overrides of a model's stored interpolation; an unset member keeps the model's.
struct InterpolationChoice {
  std::optional<InterpolationMethod> method{};
  std::optional<double> cube_edge_m{};  ///< octuplet cube edge [m]; given alone it selects octuplet
  /// The model's `stored` settings with these on top; throws InputError when the result cannot
  /// work (octuplet without a cube edge).
  [[nodiscard]] InterpolationSettings apply(InterpolationSettings stored) const;
};

}  // namespace vrreg
