// SPDX-License-Identifier: Apache-2.0
#include "arrays.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <limits>

#include "vrreg/core/check.hpp"

namespace vrreg::python {
namespace {

using Strided = Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic>, Eigen::Unaligned,
                           Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>;

// Bad input from Python is a vrreg.InputError (a ValueError) like the library's own, with the
// Python argument's name in the message.
[[noreturn]] void bad_input(const std::string& message) { throw InputError(message); }

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) {
    text += (i ? ", " : "") + std::to_string(a.shape(i));
  }
  return text + (a.ndim() == 1 ? ",)" : ")");
}

}  // namespace

py::array real_array(const py::handle& object, const char* what) {
  py::array a = py::array::ensure(object);
  if (!a) bad_input(fmt::format("{}: expected a numpy array (or a sequence)", what));
  // numpy would drop the imaginary parts in the conversion to float64, with a warning only.
  if (a.dtype().kind() == 'c') {
    bad_input(fmt::format("{}: complex numbers ({}), expected real numbers", what,
                          py::str(a.dtype()).cast<std::string>()));
  }
  // numpy converts True/False to 1/0 silently: a mask passed by mistake would become metres.
  if (a.dtype().kind() == 'b') {
    bad_input(fmt::format("{}: booleans (bool), expected real numbers", what));
  }
  return a;
}

namespace {

// A C-contiguous float64 version of `a` (the same object when it already is one).
py::array_t<double, py::array::c_style | py::array::forcecast> as_doubles(const py::array& a,
                                                                          const char* what) {
  auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!d) bad_input(fmt::format("{}: cannot convert to float64", what));
  return d;
}

void check_length(const py::array& a, const char* what, Eigen::Index n) {
  if (n >= 0 && a.shape(0) != n) {
    bad_input(
        fmt::format("{}: expected {} entries (one per point), got {}", what, n, a.shape(0)));
  }
}

template <typename Matrix>
py::array hand_over(Matrix&& matrix, std::vector<py::ssize_t> shape,
                    std::vector<py::ssize_t> strides) {
  auto* heap = new Matrix(std::move(matrix));
  py::capsule owner(heap, [](void* p) { delete static_cast<Matrix*>(p); });
  return py::array_t<double>(std::move(shape), std::move(strides), heap->data(), owner);
}

py::array read_only(py::array a) {
  a.attr("flags").attr("writeable") = false;
  return a;
}

}  // namespace

Points3 points_from(const py::handle& object, const char* what) {
  py::array a = real_array(object, what);
  // A single position (3,) is one point, as scipy's Rotation.apply takes it.
  if (a.ndim() == 1 && a.shape(0) == 3) a = a.attr("reshape")(1, 3).cast<py::array>();
  if (a.ndim() != 2 || a.shape(1) != 3) {
    bad_input(fmt::format("{}: expected an (N, 3) array of positions in metres (or one (3,) "
                          "position), got shape {}",
                          what, shape_text(a)));
  }
  const Eigen::Index n = a.shape(0);
  constexpr py::ssize_t kSize = sizeof(double);
  if (a.dtype().is(py::dtype::of<double>()) && a.strides(0) > 0 && a.strides(1) > 0 &&
      a.strides(0) % kSize == 0 && a.strides(1) % kSize == 0) {
    // Any positive strides: the one copy reads straight from numpy's memory.
    return Strided(
        static_cast<const double*>(a.data()), 3, n,
        Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(a.strides(0) / kSize, a.strides(1) / kSize));
  }
  const auto d = as_doubles(a, what);
  return Eigen::Map<const Points3>(d.data(), 3, n);
}

Eigen::VectorXd vector_from(const py::handle& object, const char* what, Eigen::Index n) {
  const py::array a = real_array(object, what);
  if (a.ndim() != 1) {
    bad_input(
        fmt::format("{}: expected a 1-D array, got shape {}", what, shape_text(a)));
  }
  check_length(a, what, n);
  const auto d = as_doubles(a, what);
  return Eigen::Map<const Eigen::VectorXd>(d.data(), d.shape(0));
}

std::vector<int> ints_from(const py::handle& object, const char* what, Eigen::Index n) {
  const py::array a = real_array(object, what);
  if (a.ndim() != 1) {
    bad_input(
        fmt::format("{}: expected a 1-D array of integers, got shape {}", what, shape_text(a)));
  }
  check_length(a, what, n);
  if (a.dtype().kind() != 'i' && a.dtype().kind() != 'u') {
    bad_input(fmt::format("{}: expected integers", what));
  }
  const auto d = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  if (a.dtype().kind() == 'u' && a.dtype().itemsize() == 8) {
    // uint64 above 2^63 would wrap to a negative int64 below; reject it by its own value.
    const auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    for (py::ssize_t i = 0; i < u.shape(0); ++i) {
      if (u.at(i) > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
        bad_input(fmt::format("{}[{}] = {} does not fit a 32-bit integer", what, i, u.at(i)));
      }
    }
  }
  std::vector<int> out;
  out.reserve(static_cast<std::size_t>(d.shape(0)));
  for (py::ssize_t i = 0; i < d.shape(0); ++i) {
    const std::int64_t v = d.at(i);
    // Never truncate silently: 2**40 is not a configuration label.
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
      bad_input(fmt::format("{}[{}] = {} does not fit a 32-bit integer", what, i, v));
    }
    out.push_back(static_cast<int>(v));
  }
  return out;
}

Eigen::MatrixXd rows_from(const py::handle& object, const char* what, Eigen::Index n,
                          Eigen::Index n_cols) {
  const py::array a = real_array(object, what);
  if (a.ndim() != 2 || (n_cols >= 0 && a.shape(1) != n_cols)) {
    bad_input(fmt::format("{}: expected an (N, {}) array, got shape {}", what,
                                      n_cols >= 0 ? std::to_string(n_cols) : "n", shape_text(a)));
  }
  check_length(a, what, n);
  const auto d = as_doubles(a, what);
  // Row-major (N, n_cols) is column-major (n_cols, N): one column per row of the array.
  return Eigen::Map<const Eigen::MatrixXd>(d.data(), d.shape(1), d.shape(0));
}

py::array to_numpy(Points3&& points) {
  const py::ssize_t n = points.cols();
  return hand_over(std::move(points), {n, 3}, {3 * sizeof(double), sizeof(double)});
}

py::array to_numpy(Eigen::VectorXd&& values) {
  const py::ssize_t n = values.size();
  return hand_over(std::move(values), {n}, {sizeof(double)});
}

py::array view_of(const Points3& points, const py::handle& owner) {
  return read_only(py::array_t<double>({static_cast<py::ssize_t>(points.cols()), py::ssize_t{3}},
                                       {3 * sizeof(double), sizeof(double)}, points.data(), owner));
}

py::array view_of(const Eigen::VectorXd& values, const py::handle& owner) {
  return read_only(py::array_t<double>({static_cast<py::ssize_t>(values.size())}, {sizeof(double)},
                                       values.data(), owner));
}

py::array matrix_copy(const Eigen::Ref<const Eigen::MatrixXd>& matrix) {
  py::array_t<double> out({matrix.rows(), matrix.cols()});
  auto m = out.mutable_unchecked<2>();
  for (Eigen::Index r = 0; r < matrix.rows(); ++r) {
    for (Eigen::Index c = 0; c < matrix.cols(); ++c) m(r, c) = matrix(r, c);
  }
  return out;
}

py::array vector_copy(const Eigen::Vector3d& vector) {
  py::array_t<double> out(3);
  for (py::ssize_t i = 0; i < 3; ++i) out.mutable_at(i) = vector(i);
  return out;
}

py::array columns_as_rows(const Eigen::Ref<const Eigen::MatrixXd>& columns) {
  return matrix_copy(columns.transpose());
}

}  // namespace vrreg::python
