#pragma once
// Internal to pipeline: one interface over the models of the whole correction field
// (docs/field-models.md), what they are fitted on and what they are asked.
#include <memory>
#include <optional>
#include <string>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/interpolation.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::pipeline_detail {

/// What a field model is fitted on: per fiducial its nominal robot position, its registered
/// position and its correction (Eq. 6), and, for the joint-space model, its joints and the robot.
struct FieldData {
  SimilarityTransform T_robot_sensor;
  Points3 fiducials_robot_m;     ///< nominal Y_j [m]
  Points3 registered_robot_m;    ///< R X_j + tau [m]
  Points3 corrections_sensor_m;  ///< epsilon_j [m]
  Eigen::MatrixXd joints_rad;    ///< one column per fiducial, or 0 x 0 without joints
  std::optional<kinematics::SerialChain> robot;  ///< the arm the joints belong to (to the marker)
  std::optional<double> noise_sd_m;  ///< sigma_noise per axis when known (Eq. 9) [m]
  double tolerance_m = 1e-6;         ///< lattice matching tolerance [m]

  /// The fiducials whose columns are `keep` (a cross-validation fold's training set).
  [[nodiscard]] FieldData subset(const std::vector<Eigen::Index>& keep) const;
  [[nodiscard]] Eigen::Index size() const { return fiducials_robot_m.cols(); }
};

/// Where a field model is asked: registered robot positions and, for the joint model, joints.
struct FieldQuery {
  Points3 registered_robot_m;  ///< R X + tau [m]
  Eigen::MatrixXd joints_rad;  ///< one column per point, or 0 x 0
};

/// Corrections predicted at a query, in the sensor frame [m]; `ok` false where the model has no
/// prediction (outside a lattice); `sd_m` the predicted standard uncertainty of each corrected
/// point's error (3D: sqrt of the per-axis variances), or empty when the model gives none.
struct FieldPredictions {
  Points3 corrections_sensor_m;
  std::vector<char> ok;
  Eigen::VectorXd sd_m;
};

/// Predictions one point at a time: `at(i)` gives point i's correction or nullopt.
template <class At>
FieldPredictions predict_pointwise(Eigen::Index n, At at) {
  FieldPredictions out;
  out.corrections_sensor_m.setZero(3, n);
  out.ok.assign(static_cast<std::size_t>(n), 0);
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::optional<Eigen::Vector3d> c = at(i);
    if (!c) continue;
    out.corrections_sensor_m.col(i) = *c;
    out.ok[static_cast<std::size_t>(i)] = 1;
  }
  return out;
}

/// A fitted model of the correction field.
class FieldModel {
 public:
  virtual ~FieldModel() = default;
  [[nodiscard]] virtual FieldPredictions predict(const FieldQuery& query) const = 0;
  [[nodiscard]] virtual InterpolationMethod method() const = 0;
  /// E.g. "kriging, Matérn 5/2 + quadratic trend, 1167 fiducials (exact)".
  [[nodiscard]] virtual std::string describe() const = 0;
  /// The same model on a subset of the fiducials (a cross-validation fold). Models whose
  /// settings are themselves fitted (kriging's hyperparameters, the joint model's degrees) keep
  /// this model's, so a fold costs a solve, not a search; the CV error is then slightly
  /// optimistic (docs/field-models.md). Default: fitted afresh.
  [[nodiscard]] virtual std::unique_ptr<FieldModel> refit(const FieldData& subset) const;
};

/// Why `method` cannot be fitted on `data` (no joints, no robot, not a lattice, too few
/// fiducials), or empty when it can be tried.
std::string field_model_unavailable(InterpolationMethod method, const FieldData& data);

/// Fits `method` (a field model, not kAuto; or kScattered, for the cross-validation table) on
/// `data`; throws InputError when it cannot.
std::unique_ptr<FieldModel> fit_field_model(InterpolationMethod method, const FieldData& data);

}  // namespace vrreg::pipeline_detail

namespace vrreg::pipeline_detail {

// One factory per model, each in its own file.
std::unique_ptr<FieldModel> fit_scattered_model(const FieldData& data);
std::unique_ptr<FieldModel> fit_trilinear_model(const FieldData& data);
std::unique_ptr<FieldModel> fit_kriging_model(const FieldData& data);
std::unique_ptr<FieldModel> fit_rbf_model(const FieldData& data);
std::unique_ptr<FieldModel> fit_joint_model(const FieldData& data);

}  // namespace vrreg::pipeline_detail
