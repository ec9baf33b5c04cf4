// SPDX-License-Identifier: Apache-2.0
// register / evaluate / correct: the front door (include/vrreg/vrreg.hpp), one call each, on
// arrays in metres or on a vrreg.Measurements read from a CSV (then exactly the command line's
// numbers). Inputs are converted with the GIL held; the C++ call runs without it.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "paths.hpp"
#include "points.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/configuration_order.hpp"
#include "vrreg/robot_io/robot_file.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::python {
namespace {

// The library's override of a model's interpolation (as --interpolation / --cube-mm do).
InterpolationChoice interpolation_choice(const std::optional<std::string>& method,
                                         const std::optional<double>& cube_edge_m) {
  InterpolationChoice c;
  if (method) c.method = parse_interpolation_method(*method);
  c.cube_edge_m = cube_edge_m;
  return c;
}

/// The arm a joint-space model needs: a built-in name ('ur5', 'lwr4', ...) or a robot file (its
/// tool the marker), as `--robot` on the command line; none when not given.
std::optional<kinematics::SerialChain> arm_of(const std::optional<PathText>& arm) {
  if (!arm) return std::nullopt;
  return io::load_robot(arm->text);
}

struct RegisterKwargs {
  std::optional<int> config;
  bool scale = false;
  bool robust = false;
  std::optional<double> sigma_rep_m;
  std::string interpolation = "linear";
  std::optional<double> cube_edge_m;
  int strategy = 0;
  std::string joint_norm = "l2";
  std::optional<std::uint64_t> seed;
  bool rigid_body = true;
  std::optional<PathText> arm;

  [[nodiscard]] RegisterOptions options() const {
    RegisterOptions o;
    o.config = config;
    o.registration.estimate_scale = scale;
    if (robust) o.robust = OutlierOptions{};
    o.sigma_rep_m = sigma_rep_m;
    o.rigid_body_statistics = rigid_body;
    o.interpolation = interpolation_choice(interpolation, cube_edge_m).apply({});
    o.procedure2.strategy = planning::strategy_from_number(strategy);
    o.procedure2.joint_norm = kinematics::parse_joint_norm(joint_norm);
    o.procedure2.seed = seed;
    o.robot = arm_of(arm);
    o.validate();
    return o;
  }
};

// A Measurements object, or arrays with their extras (which a Measurements does not take).
template <typename Run>
auto on_points(const py::handle& data, const py::handle& robot, const PointExtras& extras,
               Run&& run) {
  if (const MeasurementSet* set = as_measurements(data)) {
    VRREG_THROW_UNLESS(robot.is_none() && extras.weights.is_none() && extras.names.is_none() &&
                           extras.configs.is_none() && extras.joints.is_none() &&
                           extras.n_readings.is_none() && extras.sensor_sq_dev.is_none() &&
                           extras.sensor_q.is_none() && extras.robot_q.is_none() &&
                           extras.approach_from_q.is_none() && extras.approach_sign.is_none(),
                       "robot, weights, names, configs, joints, n_readings, sensor_sq_dev, "
                       "sensor_q, robot_q, approach_from_q and approach_sign go with arrays; a "
                       "Measurements object carries them");
    return run(*set);
  }
  const MeasuredPoints points = measured_points(data, robot, extras);
  return run(points);
}

constexpr const char* kRegisterDoc =
    R"doc(Registers fiducials: {R, tau} with Y ~ R X + tau (paper Eq. 2), the
rigid-body condition sigma_L (Eq. 1), sigma_opt / sigma_noise / rho (Eq. 9) and the RRBC
corrections (Eq. 6), into result.model.

sensor: (N, 3) measured positions, sensor frame, METRES (any strides; float32 converted), or a
  vrreg.Measurements (its fiducial rows; then robot and the per-point extras are not given).
robot: (N, 3) nominal positions, robot frame, METRES.
weights (N,), names (N labels), configs (N,) ints, joints (N, n) [rad], n_readings (N,) and
  sensor_sq_dev (N, 3) [m^2]: optional per-point extras (see vrreg::MeasuredPoints).
sensor_q, robot_q: (N, 4) unit quaternions (x, y, z, w), the rigid-body marker's measured
  orientation (sensor frame) and commanded one (robot frame): with both, the model also fits
  an orientation field (docs/orientation.md).
config: use only this configuration label. scale: also fit a uniform scale (not the paper's).
robust: reject fiducials whose correction disagrees with their neighbours' (a displaced or
  swapped marker; result.outliers) and fill them from the neighbours.
sigma_rep: robot repeatability [m] for sigma_noise and rho.
interpolation: 'linear' (grid or scattered), 'grid', 'scattered', 'octuplet', or a field
  model: 'trilinear', 'kriging', 'rbf', 'joint', 'auto' (by cross-validation); stored as
  evaluate's and correct's default. cube_edge: octuplet cube edge [m]. strategy: Procedure 2 strategy 0-3 (section 4.4),
  joint_norm 'l2' or 'linf', seed (strategy 3). rigid_body=False skips sigma_L, which costs
  O(N^2) pairs (use it for very large N). arm: the robot whose joints are given, for the
  'joint' model ('ur5', 'lwr4', ... or a robot file; stored in the model), as --robot.
Raises ValueError (vrreg.InputError) on bad shapes, NaN, fewer than 3 or collinear points.)doc";

constexpr const char* kEvaluateDoc =
    R"doc(Evaluates a model on independent targets: TRE per target and RMS_T
(Eq. 3, 4) uncorrected and RRBC-corrected (Eq. 7, 8), gamma, N_bad (section 5.1).

sensor: (N, 3) measured target positions, sensor frame, METRES, or a vrreg.Measurements (its
  target rows; as `vrreg evaluate --targets`). robot: (N, 3) nominal positions, robot frame, METRES.
names, configs, joints: optional per-target extras. sensor_q, robot_q (N, 4) quaternions
(x, y, z, w): measured and commanded orientations, for result.orientation (the model's
fiducials must carry orientations). config: evaluate this label only.
interpolation / cube_edge [m]: override the model's. strategy, joint_norm: Procedure 2 overrides.
arm: the robot for the 'joint' model (default: the model's), as --robot. refit, exact,
extrapolate: as correct(). approach_from_q, approach_sign: as correct(). Raises ValueError
(vrreg.InputError) on bad input.)doc";

constexpr const char* kCorrectDoc =
    R"doc(RRBC-corrects points measured by the sensor (Eq. 7, 8, then mapped with
{R, tau}): robot-frame positions to command, in METRES, with a status per point.

sensor: (N, 3) measured positions, sensor frame, METRES, or a vrreg.Measurements (its target rows;
  as `vrreg correct --points`). robot: (N, 3) nominal positions [m], needed by octuplet only.
names, configs, joints: optional per-point extras. sensor_q (N, 4) quaternions (x, y, z, w): the
points' measured orientations, sensor frame: result.orientation gives the orientations to command
(the model's fiducials must carry orientations, else ValueError). config, interpolation,
cube_edge [m]: override
the model's; arm: the robot for the 'joint' model (default: the model's). Points outside the
fiducials keep the uncorrected mapping and a status saying why. The model's fitted corrector is
used as saved (fit once, correct many): refit=True fits it again, exact=True corrects kriging and
rbf with the model itself instead of its table. extrapolate=True corrects a field model's points
outside its support too (status EXTRAPOLATED, with a widened predicted sd).
approach_from_q: (N, n_joints) joints the robot comes from to each point [rad] (with joints):
each joint's approach direction is the sign of joints - approach_from_q, 0 where it does not
move; or approach_sign: (N, n_joints) the directions, each -1, 0 (unknown) or 1. A model with a
lost-motion term corrects for the direction; without one (0 x 0), it answers with the term's mean
over both directions and an sd that covers either. A model without the term ignores them.)doc";

}  // namespace

void bind_pipeline(py::module_& m) {
  m.def(
      "register",
      [](const py::object& sensor, const py::object& robot, const py::object& weights,
         const py::object& names, const py::object& configs, const py::object& joints,
         const py::object& n_readings, const py::object& sensor_sq_dev, const py::object& sensor_q,
         const py::object& robot_q, std::optional<int> config, bool scale, bool robust,
         std::optional<double> sigma_rep, const std::string& interpolation,
         std::optional<double> cube_edge, int strategy, const std::string& joint_norm,
         std::optional<std::uint64_t> seed, bool rigid_body, std::optional<PathText> arm) {
        const RegisterOptions options =
            RegisterKwargs{config,    scale,    robust,     sigma_rep,  interpolation, cube_edge,
                           strategy,  joint_norm, seed,     rigid_body, arm}
                .options();
        return on_points(
            sensor, robot,
            {weights, names, configs, joints, n_readings, sensor_sq_dev, sensor_q, robot_q},
            [&](const auto& points) {
              py::gil_scoped_release nogil;
              return register_fiducials(points, options);
            });
      },
      py::arg("sensor"), py::arg("robot") = py::none(), py::kw_only(),
      py::arg("weights") = py::none(), py::arg("names") = py::none(),
      py::arg("configs") = py::none(), py::arg("joints") = py::none(),
      py::arg("n_readings") = py::none(), py::arg("sensor_sq_dev") = py::none(),
      py::arg("sensor_q") = py::none(), py::arg("robot_q") = py::none(),
      py::arg("config") = py::none(), py::arg("scale") = false, py::arg("robust") = false,
      py::arg("sigma_rep") = py::none(), py::arg("interpolation") = "linear",
      py::arg("cube_edge") = py::none(), py::arg("strategy") = 0, py::arg("joint_norm") = "l2",
      py::arg("seed") = py::none(), py::arg("rigid_body") = true, py::arg("arm") = py::none(),
      kRegisterDoc);

  m.def(
      "evaluate",
      [](const RegistrationModel& model, const py::object& sensor, const py::object& robot,
         const py::object& names, const py::object& configs, const py::object& joints,
         const py::object& sensor_q, const py::object& robot_q, const py::object& approach_from_q,
         const py::object& approach_sign, std::optional<int> config,
         std::optional<std::string> interpolation, std::optional<double> cube_edge,
         std::optional<int> strategy, std::optional<std::string> joint_norm,
         std::optional<PathText> arm, bool refit, bool exact, bool extrapolate) {
        EvaluateOptions options;
        options.config = config;
        options.refit = refit;
        options.exact = exact;
        options.extrapolate = extrapolate;
        options.robot = arm_of(arm);
        options.interpolation = interpolation_choice(interpolation, cube_edge);
        if (strategy) options.strategy = planning::strategy_from_number(*strategy);
        if (joint_norm) options.joint_norm = kinematics::parse_joint_norm(*joint_norm);
        PointExtras extras;
        extras.names = names;
        extras.configs = configs;
        extras.joints = joints;
        extras.sensor_q = sensor_q;
        extras.robot_q = robot_q;
        extras.approach_from_q = approach_from_q;
        extras.approach_sign = approach_sign;
        return on_points(sensor, robot, extras, [&](const auto& points) {
          py::gil_scoped_release nogil;
          return evaluate(model, points, options);
        });
      },
      py::arg("model"), py::arg("sensor"), py::arg("robot") = py::none(), py::kw_only(),
      py::arg("names") = py::none(), py::arg("configs") = py::none(),
      py::arg("joints") = py::none(), py::arg("sensor_q") = py::none(),
      py::arg("robot_q") = py::none(), py::arg("approach_from_q") = py::none(),
      py::arg("approach_sign") = py::none(), py::arg("config") = py::none(),
      py::arg("interpolation") = py::none(), py::arg("cube_edge") = py::none(),
      py::arg("strategy") = py::none(), py::arg("joint_norm") = py::none(),
      py::arg("arm") = py::none(), py::arg("refit") = false, py::arg("exact") = false,
      py::arg("extrapolate") = false, kEvaluateDoc);

  m.def(
      "correct",
      [](const RegistrationModel& model, const py::object& sensor, const py::object& robot,
         const py::object& names, const py::object& configs, const py::object& joints,
         const py::object& sensor_q, const py::object& approach_from_q,
         const py::object& approach_sign, std::optional<int> config,
         std::optional<std::string> interpolation, std::optional<double> cube_edge,
         std::optional<PathText> arm, bool refit, bool exact, bool extrapolate) {
        CorrectOptions options;
        options.config = config;
        options.refit = refit;
        options.exact = exact;
        options.extrapolate = extrapolate;
        options.robot = arm_of(arm);
        options.interpolation = interpolation_choice(interpolation, cube_edge);
        PointExtras extras;
        extras.names = names;
        extras.configs = configs;
        extras.joints = joints;
        extras.sensor_q = sensor_q;
        extras.approach_from_q = approach_from_q;
        extras.approach_sign = approach_sign;
        return on_points(sensor, robot, extras, [&](const auto& points) {
          py::gil_scoped_release nogil;
          return correct(model, points, options);
        });
      },
      py::arg("model"), py::arg("sensor"), py::arg("robot") = py::none(), py::kw_only(),
      py::arg("names") = py::none(), py::arg("configs") = py::none(),
      py::arg("joints") = py::none(), py::arg("sensor_q") = py::none(),
      py::arg("approach_from_q") = py::none(), py::arg("approach_sign") = py::none(),
      py::arg("config") = py::none(), py::arg("interpolation") = py::none(),
      py::arg("cube_edge") = py::none(), py::arg("arm") = py::none(), py::arg("refit") = false,
      py::arg("exact") = false, py::arg("extrapolate") = false, kCorrectDoc);
}

}  // namespace vrreg::python
