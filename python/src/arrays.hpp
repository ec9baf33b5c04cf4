// SPDX-License-Identifier: Apache-2.0
#pragma once
// numpy <-> Eigen at the module's edge. Positions are (N, 3) arrays in metres (a row a point),
// which is exactly the memory of the library's 3 x N column-major Points3: input is copied once
// (from any strides; float32 and integers converted), output is handed over without a copy.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg::python {

namespace py = pybind11;

/// `object` as a numpy array of real numbers; InputError naming `what` when it is none, or holds
/// complex numbers.
py::array real_array(const py::handle& object, const char* what);
/// An (N, 3) array of positions [m] as a point set; ValueError naming `what` on another shape.
Points3 points_from(const py::handle& array, const char* what);
/// A 1-D array of N values; ValueError naming `what` unless it has `n` entries (n < 0: any).
Eigen::VectorXd vector_from(const py::handle& array, const char* what, Eigen::Index n = -1);
/// A 1-D array of N integers; ValueError naming `what` unless it has `n` entries.
std::vector<int> ints_from(const py::handle& array, const char* what, Eigen::Index n);
/// An (N, n_cols) array as the library's column-per-row matrix (n_cols x N); n_cols < 0: any.
Eigen::MatrixXd rows_from(const py::handle& array, const char* what, Eigen::Index n,
                          Eigen::Index n_cols = -1);

/// Hands `points` to numpy as an (N, 3) array without copying.
py::array to_numpy(Points3&& points);
/// Hands `values` to numpy as a 1-D array without copying.
py::array to_numpy(Eigen::VectorXd&& values);
/// A read-only (N, 3) view of `points` kept alive by `owner` (the Python object holding them).
py::array view_of(const Points3& points, const py::handle& owner);
/// A read-only 1-D view of `values` kept alive by `owner`.
py::array view_of(const Eigen::VectorXd& values, const py::handle& owner);
/// A small fixed matrix (3 x 3 rotation, 4 x 4 pose) as a new row-major array.
py::array matrix_copy(const Eigen::Ref<const Eigen::MatrixXd>& matrix);
/// A 3-vector as a new (3,) array.
py::array vector_copy(const Eigen::Vector3d& vector);
/// A column-per-entry matrix (n_rows x N) as a new (N, n_rows) array.
py::array columns_as_rows(const Eigen::Ref<const Eigen::MatrixXd>& columns);

/// None or a value, for optional results.
template <typename T>
py::object optional_value(const std::optional<T>& value) {
  return value ? py::cast(*value) : py::none();
}

}  // namespace vrreg::python
