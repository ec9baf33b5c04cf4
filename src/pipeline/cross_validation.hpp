#pragma once
// Internal to pipeline: K-fold cross-validation of the field models on the fiducials, and the
// choice of `--interpolation auto` (docs/field-models.md).
#include <cstdint>
#include <vector>

#include "field_models.hpp"
#include "vrreg/pipeline/field_model.hpp"

namespace vrreg::pipeline_detail {

/// Fold (0..folds-1) of each of n fiducials: a seeded shuffle dealt round-robin, so folds differ
/// in size by at most one and do not follow the file's (spatial) order.
std::vector<int> assign_folds(Eigen::Index n, int folds, std::uint64_t seed);

/// One method's row: fitted on all folds but one, predicted on that one, for every fold.
CrossValidationRow cross_validate(InterpolationMethod method, const FieldData& data,
                                  const std::vector<int>& fold_of, int folds);

/// The methods `auto` chooses among, in the order of the table.
std::vector<InterpolationMethod> auto_candidates();

/// Every candidate's row and the choice: the lowest RMS among applicable methods that predicted
/// at least 95 % of the fiducials. Throws InputError when no method qualifies.
CrossValidation choose_by_cross_validation(const FieldData& data, int folds = 5,
                                           std::uint64_t seed = 1);

}  // namespace vrreg::pipeline_detail
