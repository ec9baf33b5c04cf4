// SPDX-License-Identifier: Apache-2.0
// The library's bad-input errors as Python exceptions (design.md 7): InputError and FileError are
// ValueError subclasses, so `except ValueError` catches every bad input, a missing or unreadable
// file included; FileError also carries .path and .line.
#include "bindings.hpp"
#include "vrreg/core/file_error.hpp"

namespace vrreg::python {

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
      py::object error = py::reinterpret_borrow<py::object>(file_error.ptr())(e.what());
      error.attr("path") = e.path();
      error.attr("line") = e.line();
      PyErr_SetObject(file_error.ptr(), error.ptr());
    } catch (const InputError& e) {
      input_error(e.what());
    }
  });
}

}  // namespace vrreg::python
