// The radial basis function field model (correction/rbf.hpp) behind the FieldModel interface.
// Its sd is the caller's cross-validated RMS, like the other models without a posterior.
#include <memory>

#include "field_models.hpp"
#include "vrreg/correction/rbf.hpp"

namespace vrreg::pipeline_detail {
namespace {

class RbfFieldModel final : public FieldModel {
 public:
  explicit RbfFieldModel(RbfModel model) : model_(std::move(model)) {}

  [[nodiscard]] FieldPredictions predict(const FieldQuery& query) const override {
    FieldPredictions out;
    out.corrections_sensor_m = model_.predict(query.registered_robot_m).mean_m;
    out.ok.assign(static_cast<std::size_t>(query.registered_robot_m.cols()), 1);
    return out;
  }
  [[nodiscard]] InterpolationMethod method() const override {
    return InterpolationMethod::kRbf;
  }
  [[nodiscard]] std::string describe() const override { return model_.describe(); }

 private:
  RbfModel model_;
};

}  // namespace

std::unique_ptr<FieldModel> fit_rbf_model(const FieldData& data) {
  return std::make_unique<RbfFieldModel>(
      RbfModel::fit(data.fiducials_robot_m, data.corrections_sensor_m));
}

}  // namespace vrreg::pipeline_detail
