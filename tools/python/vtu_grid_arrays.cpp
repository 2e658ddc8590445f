// vtu_grid_arrays: copies of the grid's vectors as numpy arrays of their own types and shapes.
#include "vtu_grid_arrays.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <vector>

namespace py = pybind11;

namespace hpcontact::python {
namespace {

// `values` as an array of shape (rows, columns), or (rows,) for one column.
template <typename T>
py::array_t<T> array_of(const std::vector<T>& values, std::size_t columns) {
  const auto rows = static_cast<py::ssize_t>(columns ? values.size() / columns : 0);
  py::array_t<T> out = columns == 1 ? py::array_t<T>(rows) : py::array_t<T>({rows, static_cast<py::ssize_t>(columns)});
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

}  // namespace

py::dict vtu_grid_arrays(const io::VtuGrid& grid) {
  py::dict out;
  out["points"] = array_of(grid.xyz, 3);
  out["connectivity"] = array_of(grid.connectivity, 1);
  out["offsets"] = array_of(grid.offsets, 1);
  out["types"] = array_of(grid.types, 1);
  out["p"] = array_of(grid.degrees, 1);
  std::vector<std::int64_t> triangles;
  for (const auto& triangle : grid.triangles) triangles.insert(triangles.end(), triangle.begin(), triangle.end());
  out["triangles"] = array_of(triangles, 3);
  for (const auto& array : grid.point_data)
    out[py::str(array.name)] = array_of(array.values, static_cast<std::size_t>(array.components));
  return out;
}

}  // namespace hpcontact::python
