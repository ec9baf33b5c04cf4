// SPDX-License-Identifier: Apache-2.0
// Fit once, correct many: a saved model's corrector (the simulated UR5 cell A1, seed 1: 1 167
// fiducials, registered with each method, written to model JSON and read back) correcting one
// point at a time and 10^6 points in one call, beside the peer a cell integrator would write
// instead: the 8 nearest fiducials (nanoflann kd-tree) with inverse-distance weights. scipy's
// RBFInterpolator and scikit-learn's GaussianProcessRegressor on the same cell run in
// python/benchmarks/corrector_peers.py (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <array>
#include <map>
#include <nanoflann.hpp>

#include "vrreg/core/random.hpp"
#include "vrreg/experiments/simulated_measurements.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/simulation/acquisition.hpp"
#include "vrreg/simulation/testbed.hpp"
#include "vrreg/vrreg.hpp"

namespace corrector_bench {

using vrreg::InterpolationMethod;
using vrreg::Points3;

constexpr Eigen::Index kBatch = 1'000'000;

const std::array<InterpolationMethod, 7> kMethods = {
    InterpolationMethod::kGrid,      InterpolationMethod::kScattered, InterpolationMethod::kOctuplet,
    InterpolationMethod::kTrilinear, InterpolationMethod::kKriging,   InterpolationMethod::kRbf,
    InterpolationMethod::kJoint};

const vrreg::MeasurementSet& cell() {
  static const vrreg::MeasurementSet set = vrreg::experiments::to_measurement_set(
      vrreg::simulation::simulate_dataset(vrreg::simulation::ur5_testbed(),
                                          vrreg::simulation::Dataset::kA1, {1, {}}));
  return set;
}

/// The model registered with `method` on A1, saved and read back: what a cell loads.
const vrreg::RegistrationModel& saved_model(InterpolationMethod method) {
  static std::map<InterpolationMethod, vrreg::RegistrationModel> models;
  auto it = models.find(method);
  if (it != models.end()) return it->second;
  vrreg::RegisterOptions options;
  options.interpolation.method = method;
  if (method == InterpolationMethod::kOctuplet) options.interpolation.cube_edge_m = 0.05;
  options.robot = vrreg::kinematics::ur5();
  const vrreg::RegistrationModel fitted = vrreg::register_fiducials(cell(), options).model;
  return models
      .emplace(method, vrreg::io::parse_model_json(vrreg::io::format_model_json(fitted), "a1.json"))
      .first->second;
}

/// The target rows of A1 as arrays: sensor, nominal robot, joints.
const vrreg::MeasuredPoints& targets() {
  static const vrreg::MeasuredPoints points = [] {
    vrreg::MeasuredPoints p;
    const std::vector<std::size_t> rows = cell().select(vrreg::Role::kTarget);
    p.sensor_m = cell().sensor_points(rows);
    p.robot_m = cell().robot_points(rows);
    p.joints_rad.resize(6, static_cast<Eigen::Index>(rows.size()));
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const std::vector<double>& q = cell().locations[rows[k]].q_rad;
      p.joints_rad.col(static_cast<Eigen::Index>(k)) = Eigen::Map<const Eigen::VectorXd>(q.data(), 6);
    }
    return p;
  }();
  return points;
}

/// 10^6 sensor readings inside the fiducials' volume (their registered positions, jittered).
const Points3& batch_sensor_m() {
  static const Points3 points = [] {
    const vrreg::RegistrationModel& m = saved_model(InterpolationMethod::kGrid);
    const Points3 robot = [&] {
      Points3 f(3, static_cast<Eigen::Index>(m.fiducials.size()));
      for (std::size_t j = 0; j < m.fiducials.size(); ++j)
        f.col(static_cast<Eigen::Index>(j)) = m.fiducials[j].robot_m;
      return f;
    }();
    const Eigen::Vector3d lo = robot.rowwise().minCoeff();
    const Eigen::Vector3d hi = robot.rowwise().maxCoeff();
    vrreg::Random rng(5);
    const vrreg::SimilarityTransform T_sensor_robot = m.T_robot_sensor.inverse();
    Points3 out(3, kBatch);
    for (Eigen::Index i = 0; i < kBatch; ++i) {
      out.col(i) = T_sensor_robot.apply(Eigen::Vector3d(
          rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()), rng.uniform(lo.z(), hi.z())));
    }
    return out;
  }();
  return points;
}

InterpolationMethod method_of(const benchmark::State& state) {
  return kMethods[static_cast<std::size_t>(state.range(0))];
}

// One point per call through the front door's corrector, as a cell corrects one hole at a time.
void BM_corrector_one_point(benchmark::State& state) {
  const InterpolationMethod method = method_of(state);
  const vrreg::RegistrationModel& model = saved_model(method);
  const vrreg::Corrector& corrector = *model.corrector;
  const vrreg::MeasuredPoints& t = targets();
  Eigen::Index i = 0;
  for (auto _ : state) {
    const Eigen::Index k = i++ % t.size();
    const vrreg::TargetCorrection c = corrector.correct(vrreg::CorrectionQuery(
        t.sensor_m.col(k), t.robot_m.col(k), t.joints_rad.col(k)));
    benchmark::DoNotOptimize(c.corrected_robot_m.data());
  }
  state.SetLabel(vrreg::to_string(corrector.method()));
}
BENCHMARK(BM_corrector_one_point)->DenseRange(0, 6)->Unit(benchmark::kMicrosecond);

// The same through the front door, vrreg::correct(model, points): what Python's correct() calls.
void BM_front_door_one_point(benchmark::State& state) {
  const InterpolationMethod method = method_of(state);
  const vrreg::RegistrationModel& model = saved_model(method);
  const vrreg::MeasuredPoints& t = targets();
  Eigen::Index i = 0;
  vrreg::MeasuredPoints one;
  for (auto _ : state) {
    const Eigen::Index k = i++ % t.size();
    one.sensor_m = t.sensor_m.col(k);
    one.robot_m = t.robot_m.col(k);
    one.joints_rad = t.joints_rad.col(k);
    const vrreg::CorrectResult r = vrreg::correct(model, one);
    benchmark::DoNotOptimize(r.correction.corrected_robot_m.data());
  }
  state.SetLabel(vrreg::to_string(model.corrector->method()));
}
BENCHMARK(BM_front_door_one_point)->Arg(4)->Arg(5)->Unit(benchmark::kMicrosecond);

// The exact models behind the tables: 10^4 points in one call, the model restored from its saved
// state (kriging: conditioned again, O(J^3)) and its posterior sd (O(J^2) a point) included.
void BM_corrector_exact_batch(benchmark::State& state) {
  const InterpolationMethod method = method_of(state);
  const vrreg::RegistrationModel& model = saved_model(method);
  vrreg::CorrectOptions options;
  options.exact = true;
  vrreg::MeasuredPoints points;
  points.sensor_m = batch_sensor_m().leftCols(10000);
  for (auto _ : state) {
    const vrreg::CorrectResult r = vrreg::correct(model, points, options);
    benchmark::DoNotOptimize(r.correction.corrected_robot_m.data());
  }
  state.SetItemsProcessed(state.iterations() * points.size());
  state.SetLabel(std::string(vrreg::to_string(method)) + ", exact");
}
BENCHMARK(BM_corrector_exact_batch)->Arg(4)->Arg(5)->Unit(benchmark::kMillisecond)->UseRealTime();

// 10^6 points in one call (predicted sd included); octuplet and joint need per-point nominal
// positions or joints, which random readings do not have.
void BM_corrector_batch(benchmark::State& state) {
  const InterpolationMethod method = method_of(state);
  const vrreg::Corrector& corrector = *saved_model(method).corrector;
  const Points3& sensor = batch_sensor_m();
  for (auto _ : state) {
    const vrreg::TargetCorrection c = corrector.correct(vrreg::CorrectionQuery(sensor));
    benchmark::DoNotOptimize(c.corrected_robot_m.data());
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
  state.SetLabel(vrreg::to_string(corrector.method()));
}
BENCHMARK(BM_corrector_batch)
    ->Arg(0)->Arg(1)->Arg(3)->Arg(4)->Arg(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The peer: inverse-distance weights over the 8 nearest fiducials (nanoflann), per point and
// for the batch, on the same fiducials and corrections.
struct FiducialCloud {
  Points3 points;
  [[nodiscard]] std::size_t kdtree_get_point_count() const {
    return static_cast<std::size_t>(points.cols());
  }
  [[nodiscard]] double kdtree_get_pt(std::size_t i, std::size_t d) const {
    return points(static_cast<Eigen::Index>(d), static_cast<Eigen::Index>(i));
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};
using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, FiducialCloud>,
                                                 FiducialCloud, 3, std::size_t>;

struct Idw {
  FiducialCloud cloud;
  Points3 corrections_sensor_m;
  vrreg::SimilarityTransform T;
  std::unique_ptr<Tree> tree;
  Idw() {
    const vrreg::RegistrationModel& m = saved_model(InterpolationMethod::kGrid);
    cloud.points.resize(3, static_cast<Eigen::Index>(m.fiducials.size()));
    for (std::size_t j = 0; j < m.fiducials.size(); ++j)
      cloud.points.col(static_cast<Eigen::Index>(j)) = m.fiducials[j].robot_m;
    corrections_sensor_m = m.corrections_sensor_m;
    T = m.T_robot_sensor;
    tree = std::make_unique<Tree>(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  }
  [[nodiscard]] Eigen::Vector3d correct(const Eigen::Vector3d& sensor_m) const {
    const Eigen::Vector3d at = T.apply(sensor_m);
    std::array<std::size_t, 8> index{};
    std::array<double, 8> d2{};
    tree->knnSearch(at.data(), 8, index.data(), d2.data());
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double w_sum = 0.0;
    for (std::size_t k = 0; k < 8; ++k) {
      const double w = 1.0 / (d2[k] + 1e-12);
      sum += w * corrections_sensor_m.col(index[k]);
      w_sum += w;
    }
    return T.apply(Eigen::Vector3d(sensor_m + sum / w_sum));
  }
};

const Idw& idw() {
  static const Idw peer;
  return peer;
}

void BM_peer_idw_one_point(benchmark::State& state) {
  const Idw& peer = idw();
  const vrreg::MeasuredPoints& t = targets();
  Eigen::Index i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(peer.correct(t.sensor_m.col(i++ % t.size())));
  }
}
BENCHMARK(BM_peer_idw_one_point)->Unit(benchmark::kMicrosecond);

void BM_peer_idw_batch(benchmark::State& state) {
  const Idw& peer = idw();
  const Points3& sensor = batch_sensor_m();
  Points3 out(3, kBatch);
  for (auto _ : state) {
    for (Eigen::Index i = 0; i < kBatch; ++i) out.col(i) = peer.correct(sensor.col(i));
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}
BENCHMARK(BM_peer_idw_batch)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace corrector_bench
