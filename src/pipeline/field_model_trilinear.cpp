// The trilinear field model: the filled lattice of correction/filled_lattice.hpp behind the
// FieldModel interface. It gives no uncertainty of its own (the caller's cross-validation does).
#include <memory>

#include "field_models.hpp"
#include "vrreg/correction/filled_lattice.hpp"

namespace vrreg::pipeline_detail {
namespace {

class TrilinearModel final : public FieldModel {
 public:
  TrilinearModel(FilledLattice lattice, double tolerance_m)
      : lattice_(std::move(lattice)), tolerance_m_(tolerance_m) {}

  [[nodiscard]] FieldPredictions predict(const FieldQuery& query) const override {
    return predict_pointwise(query.registered_robot_m.cols(), [&](Eigen::Index i) {
      return lattice_correction(lattice_, query.registered_robot_m.col(i), tolerance_m_);
    });
  }
  [[nodiscard]] InterpolationMethod method() const override {
    return InterpolationMethod::kTrilinear;
  }
  [[nodiscard]] std::string describe() const override {
    return "trilinear, " + lattice_.describe();
  }

 private:
  FilledLattice lattice_;
  double tolerance_m_;
};

}  // namespace

std::unique_ptr<FieldModel> fit_trilinear_model(const FieldData& data) {
  return std::make_unique<TrilinearModel>(
      fill_lattice(data.fiducials_robot_m, data.corrections_sensor_m, data.tolerance_m),
      data.tolerance_m);
}

}  // namespace vrreg::pipeline_detail
