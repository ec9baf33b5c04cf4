// SPDX-License-Identifier: Apache-2.0
// The table of correction methods: adding one is a file method_<name>.cpp and a line here.
#include <array>

#include "method_support.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

const std::array<CorrectionMethod, 7>& methods() {
  static const std::array<CorrectionMethod, 7> table = {
      detail::grid_method(),      detail::scattered_method(), detail::octuplet_method(),
      detail::trilinear_method(), detail::kriging_method(),   detail::rbf_method(),
      detail::joint_method()};
  return table;
}

}  // namespace

const CorrectionMethod& correction_method(InterpolationMethod method) {
  for (const CorrectionMethod& m : methods()) {
    if (m.method == method) return m;
  }
  VRREG_THROW_UNLESS(false, to_string(method) << " is resolved when a corrector is fitted, not a "
                                                 "correction method of its own");
}

FitOutcome fit_method(InterpolationMethod method, const CorrectorData& data,
                      const MethodSettings& settings) {
  const CorrectionMethod& m = correction_method(method);
  if (m.unavailable != nullptr) {
    std::string why = m.unavailable(data, settings);
    if (!why.empty()) return detail::not_applicable(std::move(why));
  }
  return m.fit(data, settings);
}

FitOutcome FittedMethod::refit(const CorrectorData& subset, const MethodSettings& settings) const {
  return fit_method(method(), subset, settings);
}

}  // namespace vrreg
