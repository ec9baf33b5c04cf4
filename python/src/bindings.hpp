// SPDX-License-Identifier: Apache-2.0
#pragma once
// One function per area adds its part of the module (module.cpp calls them in dependency order).
#include <pybind11/pybind11.h>

#include <string>

namespace vrreg::python {

namespace py = pybind11;

void bind_errors(py::module_& m);       // errors.cpp: InputError, FileError
/// A library message with its `option` names as Python keywords (errors.cpp).
std::string with_keywords(std::string message);
void bind_model(py::module_& m);        // model.cpp: Model, load_model
void bind_io(py::module_& m);           // io.cpp: Measurements, read_measurements
void bind_results(py::module_& m);      // results.cpp: RegisterResult, EvaluateResult, ...
void bind_pipeline(py::module_& m);     // pipeline.cpp: register, evaluate, correct
void bind_metrics(py::module_& m);      // metrics.cpp: sigma_L, noise figures, improvement
void bind_kinematics(py::module_& m);   // kinematics.cpp: fk, ik
void bind_planning(py::module_& m);     // planning.cpp: plan (Procedure 1)
void bind_simulation(py::module_& m);   // simulation.cpp: simulate
void bind_experiments(py::module_& m);  // experiments.cpp: reproduce
void bind_timing(py::module_& m);       // timing.cpp: C++-side timings for the benchmark
void bind_hand_eye(py::module_& m);     // hand_eye.cpp: estimate_marker_offset
void bind_monitoring(py::module_& m);   // monitoring.cpp: check, update

}  // namespace vrreg::python
