// A solution's VTU arrays (io::VtuGrid) as a dict of numpy arrays: what Result.fields holds.
#pragma once

#include <pybind11/pybind11.h>

#include "io/vtu_writer.hpp"

namespace hpcontact::python {

/// {"points": (n, 3), "connectivity", "offsets", "types" (VTK Lagrange cells), "p" (per cell),
/// "triangles": (m, 3) linear triangles through the nodes, then every point array: (n,) for one
/// component, (n, components) otherwise}.
pybind11::dict vtu_grid_arrays(const io::VtuGrid& grid);

}  // namespace hpcontact::python
