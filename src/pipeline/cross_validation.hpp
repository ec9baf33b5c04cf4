#pragma once
// Internal to pipeline: K-fold cross-validation of the field models on the fiducials, and the
// choice of `--interpolation auto` (docs/field-models.md).
#include <cstdint>
#include <memory>
#include <vector>

#include "field_models.hpp"
#include "vrreg/pipeline/field_model.hpp"

namespace vrreg::pipeline_detail {

/// Fold (0..folds-1) of each of n fiducials: a seeded shuffle dealt round-robin, so folds differ
/// in size by at most one and do not follow the file's (spatial) order.
std::vector<int> assign_folds(Eigen::Index n, int folds, std::uint64_t seed);

/// One method's row: fitted on all fiducials (into `full` when given), then for every fold
/// refitted (FieldModel::refit) on the others and predicted on it. The time covers both.
CrossValidationRow cross_validate(InterpolationMethod method, const FieldData& data,
                                  const std::vector<int>& fold_of, int folds,
                                  std::unique_ptr<FieldModel>* full = nullptr);

/// The methods `auto` chooses among, in the order of the table.
std::vector<InterpolationMethod> auto_candidates();

/// Every candidate's row and the choice: the lowest RMS among applicable methods that predicted
/// at least 95 % of the fiducials. Throws InputError when no method qualifies.
/// `chosen_model` (when given) receives the chosen method fitted on all fiducials.
CrossValidation choose_by_cross_validation(const FieldData& data, int folds = 5,
                                           std::uint64_t seed = 1,
                                           std::unique_ptr<FieldModel>* chosen_model = nullptr);

}  // namespace vrreg::pipeline_detail
