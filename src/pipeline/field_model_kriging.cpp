// The kriging field model (correction/kriging.hpp) behind the FieldModel interface: fitted on
// the fiducials' nominal robot positions, asked at registered positions; a corrected target's
// sd is the posterior sd of the field plus its own noise (the nugget), in quadrature.
#include <memory>

#include "field_models.hpp"
#include "vrreg/correction/kriging.hpp"

namespace vrreg::pipeline_detail {
namespace {

class KrigingFieldModel final : public FieldModel {
 public:
  explicit KrigingFieldModel(KrigingModel model) : model_(std::move(model)) {}

  [[nodiscard]] FieldPredictions predict(const FieldQuery& query) const override {
    const FieldPrediction p = model_.predict(query.registered_robot_m);
    const Eigen::Index n = query.registered_robot_m.cols();
    FieldPredictions out;
    out.corrections_sensor_m = p.mean_m;
    out.ok.assign(static_cast<std::size_t>(n), 1);
    const Eigen::Vector3d nugget_var = model_.nugget_sd_m().cwiseAbs2();
    out.sd_m.resize(n);
    for (Eigen::Index i = 0; i < n; ++i)
      out.sd_m(i) = std::sqrt((p.sd_m.col(i).cwiseAbs2() + nugget_var).sum());
    return out;
  }
  [[nodiscard]] std::string describe() const override { return model_.describe(); }

 private:
  KrigingModel model_;
};

}  // namespace

std::unique_ptr<FieldModel> fit_kriging_model(const FieldData& data) {
  KrigingOptions options;
  // The nugget is at least the fiducials' known noise: a field fitted through the noise would
  // promise more than the measurements hold.
  options.noise_sd_m = data.noise_sd_m;
  return std::make_unique<KrigingFieldModel>(
      KrigingModel::fit(data.fiducials_robot_m, data.corrections_sensor_m, options));
}

}  // namespace vrreg::pipeline_detail
