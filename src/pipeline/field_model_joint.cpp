// The joint-space error model (kinematics/joint_error_model.hpp) behind the FieldModel
// interface. It models e = y_observed - y_nominal in the robot frame as a function of the joints;
// a corrected target is R X + tau - e(q), i.e. the sensor-frame correction -R' e / s.
#include <memory>
#include <sstream>

#include "field_models.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"

namespace vrreg::pipeline_detail {
namespace {

std::vector<kinematics::JointVector> joint_columns(const Eigen::MatrixXd& joints_rad) {
  std::vector<kinematics::JointVector> out;
  out.reserve(static_cast<std::size_t>(joints_rad.cols()));
  for (Eigen::Index j = 0; j < joints_rad.cols(); ++j) out.emplace_back(joints_rad.col(j));
  return out;
}

std::unique_ptr<FieldModel> fit_joint(const FieldData& data,
                                      const kinematics::JointErrorModelOptions& options);

class JointFieldModel final : public FieldModel {
 public:
  JointFieldModel(kinematics::JointErrorModel model, const SimilarityTransform& T)
      : model_(std::move(model)), T_robot_sensor_(T) {}

  [[nodiscard]] std::unique_ptr<FieldModel> refit(const FieldData& subset) const override {
    kinematics::JointErrorModelOptions options;
    options.joint_degrees = model_.joint_degrees();
    return fit_joint(subset, options);
  }

  [[nodiscard]] FieldPredictions predict(const FieldQuery& query) const override {
    const Eigen::Index n = query.registered_robot_m.cols();
    VRREG_THROW_UNLESS(query.joints_rad.cols() == n,
                       "joint interpolation needs the joint angles of every point");
    const Points3 e_robot_m = model_.predict_m(joint_columns(query.joints_rad));
    FieldPredictions out;
    out.corrections_sensor_m =
        -(T_robot_sensor_.rotation.transpose() * e_robot_m) / T_robot_sensor_.scale;
    out.ok.assign(static_cast<std::size_t>(n), 1);
    return out;
  }
  [[nodiscard]] InterpolationMethod method() const override {
    return InterpolationMethod::kJoint;
  }
  [[nodiscard]] std::string describe() const override {
    std::ostringstream out;
    out << "joint-space model: per-joint Legendre angle errors (degrees";
    for (const int d : model_.joint_degrees()) out << ' ' << d;
    out << "), DH and marker deltas, quadratic trend; rank " << model_.rank() << " of "
        << model_.n_parameters() << " parameters";
    return out.str();
  }

 private:
  kinematics::JointErrorModel model_;
  SimilarityTransform T_robot_sensor_;
};

std::unique_ptr<FieldModel> fit_joint(const FieldData& data,
                                      const kinematics::JointErrorModelOptions& options) {
  VRREG_THROW_UNLESS(data.robot && data.joints_rad.rows() == data.robot->n_joints(),
                     "joint interpolation needs the fiducials' joint angles and the robot");
  // The errors the arm made, as the registration sees them: y_observed - y_nominal.
  const Points3 error_robot_m = data.registered_robot_m - data.fiducials_robot_m;
  return std::make_unique<JointFieldModel>(
      kinematics::JointErrorModel::fit(*data.robot, joint_columns(data.joints_rad), error_robot_m,
                                       options),
      data.T_robot_sensor);
}

}  // namespace

std::unique_ptr<FieldModel> fit_joint_model(const FieldData& data) {
  return fit_joint(data, kinematics::JointErrorModelOptions{});
}

}  // namespace vrreg::pipeline_detail
