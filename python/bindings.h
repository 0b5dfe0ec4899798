#pragma once
// The parts of the compiled module `_shockmap`, each registered on it by module.cpp. The Python
// package (shockmap/__init__.py) is the public face; these names are its implementation.

#include <pybind11/pybind11.h>

#include "records/table.h"

namespace shockmap::python {

namespace py = pybind11;

void BindComparison(py::module_& m);  // compare(), point(): the paper's problem.
void BindScene(py::module_& m);       // Scene, simulate().
void BindStudy(py::module_& m);       // Study: load and run into a database.
void BindDatabase(py::module_& m);    // Read-only queries, criteria, sizing, references.
void BindWorkflows(py::module_& m);   // report(), check_advice().

// {"columns": [...], "rows": [(...), ...]}: what pandas.DataFrame.from_records takes.
py::dict TableDict(const Table& table);

}  // namespace shockmap::python
