// The joint-space error model (kinematics/joint_error_model.hpp) behind the FieldModel
// interface. It models e = y_observed - y_nominal in the robot frame as a function of the joints;
// a corrected target is R X + tau - e(q), i.e. the sensor-frame correction -R' e / s.
#include <algorithm>
#include <iomanip>
#include <memory>
#include <sstream>

#include "field_models.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"

namespace vrreg::pipeline_detail {
namespace {

std::vector<kinematics::JointVector> joint_columns(const Eigen::MatrixXd& joints_rad) {
  std::vector<kinematics::JointVector> out;
  out.reserve(static_cast<std::size_t>(joints_rad.cols()));
  for (Eigen::Index j = 0; j < joints_rad.cols(); ++j) out.emplace_back(joints_rad.col(j));
  return out;
}

class JointFieldModel;
std::unique_ptr<JointFieldModel> fit_joint(const FieldData& data,
                                           const kinematics::JointErrorModelOptions& options);

class JointFieldModel final : public FieldModel {
 public:
  JointFieldModel(kinematics::JointErrorModel model, const SimilarityTransform& T)
      : model_(std::move(model)), T_robot_sensor_(T) {}

  [[nodiscard]] std::unique_ptr<FieldModel> refit(const FieldData& subset) const override {
    kinematics::JointErrorModelOptions options;
    options.joint_degrees = model_.joint_degrees();
    options.periodic_terms = model_.periodic_terms();
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
  [[nodiscard]] const kinematics::JointErrorModel& model() const { return model_; }
  [[nodiscard]] std::string describe() const override {
    std::ostringstream out;
    out << "joint-space model: per-joint Legendre angle errors (degrees";
    for (const int d : model_.joint_degrees()) out << ' ' << d;
    out << ")";
    const char* sep = ", cyclic errors (period): ";
    for (const kinematics::JointPeriodicTerm& t : model_.periodic_terms()) {
      out << sep << "joint " << t.joint + 1 << " " << std::setprecision(4)
          << 360.0 / t.omega_per_rad << " deg";
      sep = ", ";
    }
    out << ", DH and marker deltas, quadratic trend; rank " << model_.rank() << " of "
        << model_.n_parameters() << " parameters";
    return out.str();
  }

 private:
  kinematics::JointErrorModel model_;
  SimilarityTransform T_robot_sensor_;
};

// Least squares needs redundancy: with fewer equations per identified parameter the fit follows
// the noise, and its cross-validation, on 4/5 of the fiducials, is no guide to it. The 27-fiducial
// cube of A1 identifies 42-52 parameters from 81 equations: on seeds 1-8 it corrected the targets to
// 0.16-2.6 mm (octuplet RRBC 0.18-0.27 mm), its sd up to 7 times too large. The thinned A1 grid
// identifies ~60 from 630 and reaches the noise floor. Only the fit on all fiducials is checked:
// cross-validation refits the same parameters on fewer.
constexpr int kMinEquationsPerParameter = 3;

// Below this the fiducials' nominal positions are the robot's forward kinematics to one marker.
constexpr double kNominalMismatchM = 1e-4;

// Where the marker sits on the flange, from the fiducials' nominal positions Y_j = T_flange(q_j) p
// (least squares: the mean of R_j' (Y_j - t_j)); so the robot needs no tool of its own. Throws when
// the nominal positions are not this robot's kinematics (a wrong --robot).
Eigen::Vector3d marker_on_flange_m(const FieldData& data) {
  const kinematics::SerialChain flange = data.robot->with_tool(Eigen::Isometry3d::Identity());
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::vector<Eigen::Isometry3d> poses;
  for (Eigen::Index j = 0; j < data.size(); ++j) {
    poses.push_back(kinematics::forward_kinematics(flange, data.joints_rad.col(j)));
    sum += poses.back().linear().transpose() *
           (data.fiducials_robot_m.col(j) - poses.back().translation());
  }
  const Eigen::Vector3d p_m = sum / static_cast<double>(data.size());
  double worst_m = 0.0;
  for (Eigen::Index j = 0; j < data.size(); ++j) {
    worst_m = std::max(worst_m, (poses[static_cast<std::size_t>(j)] * p_m -
                                 data.fiducials_robot_m.col(j)).norm());
  }
  VRREG_THROW_UNLESS(worst_m <= kNominalMismatchM,
                     "the fiducials' robot positions are not " << data.robot->name()
                         << "'s forward kinematics of their joints to one marker (off by up to "
                         << worst_m * 1e3 << " mm): another --robot?");
  return p_m;
}

std::unique_ptr<JointFieldModel> fit_joint(const FieldData& data,
                                           const kinematics::JointErrorModelOptions& options) {
  VRREG_THROW_UNLESS(data.robot && data.joints_rad.rows() == data.robot->n_joints(),
                     "joint interpolation needs the fiducials' joint angles and the robot");
  const Eigen::Vector3d p_flange_marker_m = marker_on_flange_m(data);
  // The errors the arm made, as the registration sees them: y_observed - y_nominal.
  const Points3 error_robot_m = data.registered_robot_m - data.fiducials_robot_m;
  return std::make_unique<JointFieldModel>(
      kinematics::JointErrorModel::fit(*data.robot, joint_columns(data.joints_rad), error_robot_m,
                                       options, p_flange_marker_m),
      data.T_robot_sensor);
}

}  // namespace

std::unique_ptr<FieldModel> fit_joint_model(const FieldData& data) {
  std::unique_ptr<JointFieldModel> fitted = fit_joint(data, kinematics::JointErrorModelOptions{});
  const int rank = fitted->model().rank();
  const Eigen::Index equations = 3 * data.size();
  VRREG_THROW_UNLESS(equations >= kMinEquationsPerParameter * rank,
                     "the joint-space model identifies "
                         << rank << " parameters from " << data.size() << " fiducials ("
                         << equations << " equations); it needs at least "
                         << kMinEquationsPerParameter << " equations per parameter, i.e. "
                         << (kMinEquationsPerParameter * rank + 2) / 3 << " fiducials");
  return fitted;
}

}  // namespace vrreg::pipeline_detail
