// SPDX-License-Identifier: Apache-2.0
#include "vrreg/pipeline/interpolation_choice.hpp"

namespace vrreg {

InterpolationSettings InterpolationChoice::apply(InterpolationSettings stored) const {
  if (method) stored.method = *method;
  if (cube_edge_m) {
    stored.cube_edge_m = *cube_edge_m;
    if (!method) stored.method = InterpolationMethod::kOctuplet;
  }
  stored.validate();
  return stored;
}

}  // namespace vrreg
