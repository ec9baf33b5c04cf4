// The joint field model behind the FieldModel interface (docs/field-models.md).
#include <memory>

#include "field_models.hpp"
#include "vrreg/core/check.hpp"

namespace vrreg::pipeline_detail {

std::unique_ptr<FieldModel> fit_joint_model(const FieldData& /*data*/) {
  VRREG_THROW_UNLESS(false, "joint interpolation is not built yet");
}

}  // namespace vrreg::pipeline_detail
