// The kriging field model (correction/kriging.hpp) behind the FieldModel interface: fitted on
// the fiducials' nominal robot positions, asked at registered positions; a corrected target's
// sd is the posterior sd of the field plus its own noise (the nugget), in quadrature.
#include <array>
#include <cmath>
#include <memory>

#include "field_models.hpp"
#include "vrreg/correction/kriging.hpp"

namespace vrreg::pipeline_detail {
namespace {

class KrigingFieldModel final : public FieldModel {
 public:
  KrigingFieldModel(KrigingModel model, KrigingOptions options)
      : model_(std::move(model)), options_(std::move(options)) {}

  [[nodiscard]] std::unique_ptr<FieldModel> refit(const FieldData& subset) const override {
    std::array<KrigingHyperparameters, 3> h;
    for (std::size_t a = 0; a < 3; ++a) h[a] = model_.axes()[a].hyperparameters;
    return std::make_unique<KrigingFieldModel>(
        KrigingModel::with_hyperparameters(subset.fiducials_robot_m, subset.corrections_sensor_m,
                                           h, options_),
        options_);
  }

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
  [[nodiscard]] InterpolationMethod method() const override {
    return InterpolationMethod::kKriging;
  }
  [[nodiscard]] std::string describe() const override { return model_.describe(); }

 private:
  KrigingModel model_;
  KrigingOptions options_;
};

}  // namespace

std::unique_ptr<FieldModel> fit_kriging_model(const FieldData& data) {
  KrigingOptions options;
  // The nugget is at least the fiducials' known noise: a field fitted through the noise would
  // promise more than the measurements hold.
  options.noise_sd_m = data.noise_sd_m;
  return std::make_unique<KrigingFieldModel>(
      KrigingModel::fit(data.fiducials_robot_m, data.corrections_sensor_m, options), options);
}

}  // namespace vrreg::pipeline_detail
