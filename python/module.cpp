// The compiled module: the library's errors as Python exceptions, then its parts.

#include "core/input_error.h"
#include "db/sqlite_handle.h"
#include "python/bindings.h"

PYBIND11_MODULE(_shockmap, m) {
  namespace py = pybind11;
  m.doc() = "shockmap's library, compiled (docs/python.md); import the package shockmap instead";
  m.attr("__version__") = SHOCKMAP_VERSION_STRING;
  // Bad input (a file, a key, a value out of range) carries the command line's own message.
  py::register_exception<shockmap::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<shockmap::DbError>(m, "DatabaseError", PyExc_RuntimeError);
  shockmap::python::BindComparison(m);
  shockmap::python::BindScene(m);
  shockmap::python::BindStudy(m);
  shockmap::python::BindDatabase(m);
  shockmap::python::BindWorkflows(m);
}
