// SPDX-License-Identifier: Apache-2.0
#pragma once
// Path arguments take what open() takes: a str or any os.PathLike (pathlib.Path), read in the
// file system's encoding.
#include <pybind11/pybind11.h>

#include <string>

namespace vrreg::python {

/// A file path from Python (or a robot: a built-in name or a robot file).
struct PathText {
  std::string text;
};

}  // namespace vrreg::python

namespace pybind11::detail {

template <>
struct type_caster<vrreg::python::PathText> {
  PYBIND11_TYPE_CASTER(vrreg::python::PathText, const_name("str | os.PathLike[str]"));

  bool load(handle source, bool /*convert*/) {
    PyObject* path = PyOS_FSPath(source.ptr());  // str or bytes, also from __fspath__
    if (path == nullptr) {
      PyErr_Clear();  // not a path: pybind11 raises TypeError naming the argument types
      return false;
    }
    PyObject* bytes = nullptr;
    const bool encoded = PyUnicode_FSConverter(path, &bytes) != 0;
    Py_DECREF(path);
    if (!encoded) {
      PyErr_Clear();
      return false;
    }
    value.text.assign(PyBytes_AS_STRING(bytes), static_cast<std::size_t>(PyBytes_GET_SIZE(bytes)));
    Py_DECREF(bytes);
    return true;
  }

  static handle cast(const vrreg::python::PathText& path, return_value_policy /*policy*/,
                     handle /*parent*/) {
    return PyUnicode_DecodeFSDefaultAndSize(path.text.data(),
                                            static_cast<Py_ssize_t>(path.text.size()));
  }
};

}  // namespace pybind11::detail
