// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/corrector_data.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg {

CorrectorData CorrectorData::of(const SimilarityTransform& T_robot_sensor,
                                const ConstPoints3Ref& fiducials_sensor_m,
                                const ConstPoints3Ref& fiducials_robot_m,
                                const ConstPoints3Ref& corrections_sensor_m) {
  CorrectorData out;
  out.T_robot_sensor = T_robot_sensor;
  out.fiducials_robot_m = fiducials_robot_m;
  out.corrections_sensor_m = corrections_sensor_m;
  out.registered_robot_m.resize(3, fiducials_sensor_m.cols());
  for (Eigen::Index j = 0; j < fiducials_sensor_m.cols(); ++j) {
    out.registered_robot_m.col(j) = T_robot_sensor.apply(Eigen::Vector3d(fiducials_sensor_m.col(j)));
  }
  return out;
}

CorrectorData CorrectorData::subset(const std::vector<Eigen::Index>& keep) const {
  CorrectorData out;
  out.T_robot_sensor = T_robot_sensor;
  out.robot = robot;
  out.noise_sd_m = noise_sd_m;
  out.values = values;
  const auto n = static_cast<Eigen::Index>(keep.size());
  out.fiducials_robot_m.resize(3, n);
  out.registered_robot_m.resize(3, n);
  out.corrections_sensor_m.resize(3, n);
  if (has_joints()) out.joints_rad.resize(joints_rad.rows(), n);
  if (has_approach()) out.approach_sign.resize(approach_sign.rows(), n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index j = keep[static_cast<std::size_t>(i)];
    out.fiducials_robot_m.col(i) = fiducials_robot_m.col(j);
    out.registered_robot_m.col(i) = registered_robot_m.col(j);
    out.corrections_sensor_m.col(i) = corrections_sensor_m.col(j);
    if (has_joints()) out.joints_rad.col(i) = joints_rad.col(j);
    if (has_approach()) out.approach_sign.col(i) = approach_sign.col(j);
    if (!sequence.empty()) out.sequence.push_back(sequence[static_cast<std::size_t>(j)]);
    if (!configs.empty()) out.configs.push_back(configs[static_cast<std::size_t>(j)]);
  }
  return out;
}

void CorrectorData::validate() const {
  const Eigen::Index n = size();
  VRREG_THROW_UNLESS(n > 0, "the model has no fiducials to correct with");
  VRREG_THROW_UNLESS(registered_robot_m.cols() == n && corrections_sensor_m.cols() == n,
                     "the model has " << corrections_sensor_m.cols() << " fiducial corrections and "
                                      << registered_robot_m.cols() << " registered positions for "
                                      << n << " fiducials");
  VRREG_THROW_UNLESS(corrections_sensor_m.allFinite(),
                     "the model's fiducial corrections are not all finite");
  const SimilarityTransform& T = T_robot_sensor;
  VRREG_THROW_UNLESS(T.rotation.allFinite() && T.translation_m.allFinite() &&
                         std::isfinite(T.scale) && T.scale > 0.0,
                     "the model's transform is not finite (scale " << T.scale << ")");
  for (Eigen::Index j = 0; j < n; ++j) {
    VRREG_THROW_UNLESS(fiducials_robot_m.col(j).allFinite(),
                       "fiducial " << j << " has no finite nominal robot position");
  }
  VRREG_THROW_UNLESS(registered_robot_m.allFinite(),
                     "the fiducials' registered positions are not all finite");
  VRREG_THROW_UNLESS(sequence.empty() || sequence.size() == static_cast<std::size_t>(n),
                     "got " << sequence.size() << " sequence numbers for " << n << " fiducials");
  VRREG_THROW_UNLESS(configs.empty() || configs.size() == static_cast<std::size_t>(n),
                     "got " << configs.size() << " configuration labels for " << n
                            << " fiducials");
  VRREG_THROW_UNLESS(!has_joints() || (joints_rad.cols() == n && joints_rad.allFinite()),
                     "the fiducials' joints are " << joints_rad.rows() << " x "
                                                  << joints_rad.cols() << " for " << n
                                                  << " fiducials, or not finite");
  VRREG_THROW_UNLESS(!has_approach() || (approach_sign.rows() == joints_rad.rows() &&
                                         approach_sign.cols() == n &&
                                         (approach_sign.array().abs() <= 1.0).all()),
                     "the fiducials' approach directions are "
                         << approach_sign.rows() << " x " << approach_sign.cols() << " for "
                         << joints_rad.rows() << " joints x " << n
                         << " fiducials, or not signs (-1, 0, +1)");
}

}  // namespace vrreg
