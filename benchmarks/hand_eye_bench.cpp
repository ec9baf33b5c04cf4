// SPDX-License-Identifier: Apache-2.0
// Marker-offset estimation (hand-eye registration) beside OpenCV's
// calibrateRobotWorldHandEye (Shah and Li methods) on the same simulated rigid-body data: the
// tracker reads the marker's full pose (position noise per axis, small orientation noise), the
// robot's flange poses are exact. vrreg uses the positions only; OpenCV needs the orientations.
// Accuracy (RMS over 50 noise seeds) is reported as counters; time per solve by the benchmark.
// Results: docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "vrreg/core/random.hpp"
#include "vrreg/registration/marker_offset.hpp"

#ifdef VRREG_HAVE_OPENCV
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#endif

namespace {

constexpr double kPositionSigmaM = 0.058e-3;                  // the paper's sigma_opt per reading
constexpr double kOrientationSigmaRad = 0.05 * M_PI / 180.0;  // a rigid body of ~100 mm
constexpr int kAccuracySeeds = 50;

struct Truth {
  Eigen::Isometry3d T_robot_sensor = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_flange_marker = Eigen::Isometry3d::Identity();
};

struct HandEyeData {
  std::vector<Eigen::Isometry3d> T_robot_flange;
  std::vector<Eigen::Isometry3d> T_sensor_marker;  // what the tracker reads (noisy)
  vrreg::Points3 markers_sensor_m;
};

Truth make_truth() {
  vrreg::Random rng(4711);
  Truth t;
  t.T_robot_sensor.linear() = rng.rotation();
  t.T_robot_sensor.translation() = Eigen::Vector3d(1.6, -0.9, 1.3);
  t.T_flange_marker.linear() = rng.rotation();
  t.T_flange_marker.translation() = Eigen::Vector3d(0.035, -0.025, 0.085);
  return t;
}

// n flange poses in a 0.3 m box, tool down, tilted up to 20 deg about two axes.
HandEyeData make_data(const Truth& truth, int n, std::uint64_t seed) {
  vrreg::Random layout(99);
  vrreg::Random noise(seed);
  HandEyeData d;
  d.markers_sensor_m.resize(3, n);
  const Eigen::Isometry3d T_sensor_robot = truth.T_robot_sensor.inverse();
  const double tilt = 20.0 * M_PI / 180.0;
  for (int j = 0; j < n; ++j) {
    Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
    f.linear() = (Eigen::AngleAxisd(layout.uniform(-tilt, tilt), Eigen::Vector3d::UnitX()) *
                  Eigen::AngleAxisd(layout.uniform(-tilt, tilt), Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
    f.translation() = Eigen::Vector3d(0.45 + layout.uniform(-0.15, 0.15),
                                      layout.uniform(-0.15, 0.15), 0.3 + layout.uniform(-0.1, 0.1));
    d.T_robot_flange.push_back(f);
    Eigen::Isometry3d m = T_sensor_robot * f * truth.T_flange_marker;
    m.translation() += noise.normal3(kPositionSigmaM);
    const Eigen::Vector3d w = noise.normal3(kOrientationSigmaRad);
    m.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix() * m.linear();
    d.T_sensor_marker.push_back(m);
    d.markers_sensor_m.col(j) = m.translation();
  }
  return d;
}

struct Estimate {
  Eigen::Isometry3d T_robot_sensor = Eigen::Isometry3d::Identity();
  Eigen::Vector3d p_flange_marker_m = Eigen::Vector3d::Zero();
};

Estimate vrreg_estimate(const HandEyeData& d) {
  const vrreg::MarkerOffsetResult r =
      vrreg::estimate_marker_offset(d.T_robot_flange, d.markers_sensor_m);
  Estimate e;
  e.T_robot_sensor = r.T_robot_sensor.isometry();
  e.p_flange_marker_m = r.p_flange_marker_m;
  return e;
}

#ifdef VRREG_HAVE_OPENCV
// OpenCV: cTw wTb = cTg gTb with c = marker, w = sensor, g = flange, b = robot base.
Estimate opencv_estimate(const HandEyeData& d, cv::RobotWorldHandEyeCalibrationMethod method) {
  std::vector<cv::Mat> R_world2cam, t_world2cam, R_base2gripper, t_base2gripper;
  for (std::size_t j = 0; j < d.T_robot_flange.size(); ++j) {
    const Eigen::Isometry3d A = d.T_sensor_marker[j].inverse();  // marker <- sensor
    const Eigen::Isometry3d B = d.T_robot_flange[j].inverse();   // flange <- base
    cv::Mat ra, ta, rb, tb;
    cv::eigen2cv(Eigen::Matrix3d(A.linear()), ra);
    cv::eigen2cv(Eigen::Vector3d(A.translation()), ta);
    cv::eigen2cv(Eigen::Matrix3d(B.linear()), rb);
    cv::eigen2cv(Eigen::Vector3d(B.translation()), tb);
    R_world2cam.push_back(ra);
    t_world2cam.push_back(ta);
    R_base2gripper.push_back(rb);
    t_base2gripper.push_back(tb);
  }
  cv::Mat R_base2world, t_base2world, R_gripper2cam, t_gripper2cam;
  cv::calibrateRobotWorldHandEye(R_world2cam, t_world2cam, R_base2gripper, t_base2gripper,
                                 R_base2world, t_base2world, R_gripper2cam, t_gripper2cam, method);
  Eigen::Matrix3d rx, rz;
  Eigen::Vector3d tx, tz;
  cv::cv2eigen(R_base2world, rx);
  cv::cv2eigen(t_base2world, tx);
  cv::cv2eigen(R_gripper2cam, rz);
  cv::cv2eigen(t_gripper2cam, tz);
  Eigen::Isometry3d T_sensor_robot = Eigen::Isometry3d::Identity();
  T_sensor_robot.linear() = rx;
  T_sensor_robot.translation() = tx;
  Estimate e;
  e.T_robot_sensor = T_sensor_robot.inverse();
  e.p_flange_marker_m = -rz.transpose() * tz;  // marker origin in the flange frame
  return e;
}
#endif

// RMS over seeds of the rotation error [deg], translation error [mm] and offset error [mm].
template <typename Solve>
void accuracy_counters(benchmark::State& state, int n, Solve solve) {
  const Truth truth = make_truth();
  double rot2 = 0.0, tr2 = 0.0, p2 = 0.0;
  for (int s = 0; s < kAccuracySeeds; ++s) {
    const Estimate e = solve(make_data(truth, n, 1000 + static_cast<std::uint64_t>(s)));
    const double rot =
        Eigen::AngleAxisd(e.T_robot_sensor.linear() * truth.T_robot_sensor.linear().transpose())
            .angle();
    rot2 += rot * rot;
    tr2 += (e.T_robot_sensor.translation() - truth.T_robot_sensor.translation()).squaredNorm();
    p2 += (e.p_flange_marker_m - truth.T_flange_marker.translation()).squaredNorm();
  }
  state.counters["rot_err_deg"] = std::sqrt(rot2 / kAccuracySeeds) * 180.0 / M_PI;
  state.counters["tau_err_mm"] = 1e3 * std::sqrt(tr2 / kAccuracySeeds);
  state.counters["p_err_mm"] = 1e3 * std::sqrt(p2 / kAccuracySeeds);
}

void BM_vrreg_marker_offset(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const HandEyeData d = make_data(make_truth(), n, 1);
  for (auto _ : state) {
    auto r = vrreg_estimate(d);
    benchmark::DoNotOptimize(r);
  }
  accuracy_counters(state, n, vrreg_estimate);
}
BENCHMARK(BM_vrreg_marker_offset)->Arg(20)->Arg(60)->Arg(200)->Unit(benchmark::kMicrosecond);

#ifdef VRREG_HAVE_OPENCV
void run_opencv(benchmark::State& state, cv::RobotWorldHandEyeCalibrationMethod method) {
  const int n = static_cast<int>(state.range(0));
  const auto solve = [method](const HandEyeData& d) { return opencv_estimate(d, method); };
  const HandEyeData d = make_data(make_truth(), n, 1);
  for (auto _ : state) {
    auto r = solve(d);
    benchmark::DoNotOptimize(r);
  }
  accuracy_counters(state, n, solve);
}

void BM_opencv_robot_world_hand_eye_shah(benchmark::State& state) {
  run_opencv(state, cv::CALIB_ROBOT_WORLD_HAND_EYE_SHAH);
}
void BM_opencv_robot_world_hand_eye_li(benchmark::State& state) {
  run_opencv(state, cv::CALIB_ROBOT_WORLD_HAND_EYE_LI);
}
BENCHMARK(BM_opencv_robot_world_hand_eye_shah)
    ->Arg(20)
    ->Arg(60)
    ->Arg(200)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_opencv_robot_world_hand_eye_li)
    ->Arg(20)
    ->Arg(60)
    ->Arg(200)
    ->Unit(benchmark::kMicrosecond);
#endif

}  // namespace
