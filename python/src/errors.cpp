// pgamesh.InputError: the library's InputError (a file that cannot be read, with the position of
// the problem) as a Python exception. It derives from ValueError, so `except ValueError` catches
// every bad input, and carries the position as attributes: file, line and column (text formats),
// byte_offset (binary formats); the attributes that do not apply are None.
#include "bindings.hpp"
#include "pgamesh/core/input_error.hpp"

namespace pgamesh::python {

void bind_errors(py::module_& m) {
  // Never destroyed: the type lives as long as the interpreter, and a static py::object would be
  // released after the interpreter has finalised.
  static auto& type = *new py::exception<InputError>(m, "InputError", PyExc_ValueError);
  type.doc() =
      "A file (or bytes) that cannot be read as a mesh. str() is 'FILE:LINE:COL: problem' or "
      "'FILE: byte OFFSET: problem'; the attributes file, line, column and byte_offset give the "
      "position (None where they do not apply).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      const InputPosition& at = e.where();
      py::object error = py::reinterpret_borrow<py::object>(type.ptr())(e.what());
      error.attr("file") = e.file();
      error.attr("line") = at.has_line ? py::cast(at.line) : py::none();
      error.attr("column") = at.has_line && at.column ? py::cast(at.column) : py::none();
      error.attr("byte_offset") = at.has_line ? py::none() : py::cast(at.byte_offset);
      PyErr_SetObject(type.ptr(), error.ptr());
    }
  });
}

}  // namespace pgamesh::python
