// Scattered (Delaunay, Eq. 7) interpolation behind the FieldModel interface, so that the paper's
// linear weights stand in the cross-validation table beside the field models.
#include <memory>

#include "field_models.hpp"
#include "vrreg/correction/scattered.hpp"

namespace vrreg::pipeline_detail {
namespace {

class ScatteredModel final : public FieldModel {
 public:
  explicit ScatteredModel(const FieldData& data)
      : stencils_(data.fiducials_robot_m, data.tolerance_m),
        corrections_sensor_m_(data.corrections_sensor_m) {}

  [[nodiscard]] FieldPredictions predict(const FieldQuery& query) const override {
    return predict_pointwise(
        query.registered_robot_m.cols(), [&](Eigen::Index i) -> std::optional<Eigen::Vector3d> {
          const Stencil s = stencils_.stencil(query.registered_robot_m.col(i));
          if (s.status != StencilStatus::kOk) return std::nullopt;
          return interpolate_correction(s, corrections_sensor_m_);
        });
  }
  [[nodiscard]] InterpolationMethod method() const override {
    return InterpolationMethod::kScattered;
  }
  [[nodiscard]] std::string describe() const override { return stencils_.describe(); }

 private:
  ScatteredStencils stencils_;
  Points3 corrections_sensor_m_;
};

}  // namespace

std::unique_ptr<FieldModel> fit_scattered_model(const FieldData& data) {
  return std::make_unique<ScatteredModel>(data);
}

}  // namespace vrreg::pipeline_detail
