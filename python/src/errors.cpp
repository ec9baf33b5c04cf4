// SPDX-License-Identifier: Apache-2.0
// The library's bad-input errors as Python exceptions (design.md 7): InputError and FileError are
// ValueError subclasses, so `except ValueError` catches every bad input, a missing or unreadable
// file included; FileError also carries .path and .line.
#include <array>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/core/format.hpp"

namespace vrreg::python {

// The library names an option in its messages as `name`; Python says its keyword argument.
// Every option keeps its name but the robot, which evaluate, correct and register take as arm=.
std::string with_keywords(std::string message) {
  static constexpr std::array<OptionWord, 10> kKeywords{{
      {"config", "config="},
      {"cube_edge", "cube_edge="},
      {"interpolation", "interpolation="},
      {"joint_norm", "joint_norm="},
      {"robot", "arm="},
      {"robust", "robust="},
      {"scale", "scale="},
      {"seed", "seed="},
      {"sigma_rep", "sigma_rep="},
      {"strategy", "strategy="},
  }};
  return with_option_words(std::move(message), kKeywords);
}

void bind_errors(py::module_& m) {
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<FileError> file_error(m, "FileError", input_error.ptr());
  input_error.doc() = "Bad input (shape, NaN, too few or collinear points, ...): a ValueError.";
  file_error.doc() =
      "Bad, missing or unreadable file: a ValueError; .path and .line (0: no line) say where.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const FileError& e) {
      // An instance (not just the type and text) so that .path and .line can be set on it.
      py::object error =
          py::reinterpret_borrow<py::object>(file_error.ptr())(with_keywords(e.what()));
      error.attr("path") = e.path();
      error.attr("line") = e.line();
      PyErr_SetObject(file_error.ptr(), error.ptr());
    } catch (const InputError& e) {
      input_error(with_keywords(e.what()).c_str());
    }
  });
}

}  // namespace vrreg::python
