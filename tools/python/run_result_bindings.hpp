// The typed result of a scene run (driver::RunResult and its parts) as Python classes with
// read-only attributes, so that Python programs read fields, not dict keys.
#pragma once

#include <pybind11/pybind11.h>

namespace hpcontact::python {

void bind_run_result(pybind11::module_& m);

}  // namespace hpcontact::python
