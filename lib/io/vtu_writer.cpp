// write_vtu.
#include "io/vtu_writer.hpp"

#include <fmt/format.h>

#include "assembly/cell_values.hpp"
#include "io/atomic_file.hpp"

namespace hpcontact::io {

void write_vtu(const std::filesystem::path& path, const space::H1Space& space, const Eigen::VectorXd& u,
               int subdivisions) {
  std::string points, values, connectivity, offsets, types;
  int n_points = 0, n_cells = 0;
  for (int c = 0; c < space.mesh().n_cells(); ++c) {
    const int k = subdivisions > 0 ? subdivisions : std::max(space.cell_degree(c), 1);
    std::vector<double> t(k + 1);
    for (int i = 0; i <= k; ++i) t[i] = -1.0 + 2.0 * i / k;
    const auto cell = assembly::tabulate_cell(space, c, t, t);
    const auto& shapes = space.cell_shapes(c);
    Eigen::VectorXd local(shapes.size());
    for (std::size_t s = 0; s < shapes.size(); ++s) local(s) = shapes[s].dof >= 0 ? u(shapes[s].dof) : 0.0;
    const Eigen::VectorXd u_points = cell.values * local;
    const int first = n_points;
    for (int q = 0; q < cell.points.rows(); ++q) {
      points += fmt::format("{:.17g} {:.17g} 0\n", cell.points(q, 0), cell.points(q, 1));
      values += fmt::format("{:.17g}\n", u_points(q));
    }
    n_points += static_cast<int>(cell.points.rows());
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i) {
        const int a = first + j * (k + 1) + i;
        connectivity += fmt::format("{} {} {} {}\n", a, a + 1, a + k + 2, a + k + 1);
        offsets += fmt::format("{}\n", 4 * (++n_cells));
        types += "9\n";  // VTK_QUAD
      }
  }
  AtomicFile file(path);
  file.stream() << "<?xml version=\"1.0\"?>\n"
                << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                << "<UnstructuredGrid>\n"
                << fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n_points, n_cells)
                << "<PointData Scalars=\"u\">\n<DataArray type=\"Float64\" Name=\"u\" format=\"ascii\">\n"
                << values << "</DataArray>\n</PointData>\n"
                << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
                << points << "</DataArray>\n</Points>\n<Cells>\n"
                << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n"
                << connectivity << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n"
                << offsets << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n"
                << types << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  file.commit();
}

}  // namespace hpcontact::io
