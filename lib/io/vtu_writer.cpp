// write_vtu_fields and the scalar and elastic fields written through it.
#include "io/vtu_writer.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/atomic_file.hpp"

namespace hpcontact::io {
namespace {

// A cell's reference cell cut into k × k quadrilaterals (square) or k² triangles (triangle): the
// lattice points and the sub-cells' corners (counterclockwise) as indices into them.
struct Subdivision {
  assembly::ReferencePoints points;
  std::vector<std::vector<int>> cells;
  int vtk_type = 9;  // VTK_QUAD; VTK_TRIANGLE = 5
};

Subdivision subdivide(mesh::CellType type, int k) {
  Subdivision out;
  std::vector<double> t(k + 1);
  for (int i = 0; i <= k; ++i) t[i] = -1.0 + 2.0 * i / k;
  if (type == mesh::CellType::quadrilateral) {
    out.points = assembly::tensor_points(t, t);
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i) {
        const int a = j * (k + 1) + i;
        out.cells.push_back({a, a + 1, a + k + 2, a + k + 1});
      }
    return out;
  }
  out.vtk_type = 5;
  std::vector<std::vector<int>> index(k + 1);
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i + j <= k; ++i) {
      index[j].push_back(out.points.size());
      out.points.xi.push_back(t[i]);
      out.points.eta.push_back(t[j]);
    }
  for (int j = 0; j < k; ++j)
    for (int i = 0; i + j < k; ++i) {
      out.cells.push_back({index[j][i], index[j][i + 1], index[j + 1][i]});
      if (i + j + 1 < k) out.cells.push_back({index[j][i + 1], index[j + 1][i + 1], index[j + 1][i]});
    }
  return out;
}

}  // namespace

void write_vtu_fields(const std::filesystem::path& path, const space::H1Space& space,
                      const std::vector<VtuField>& fields, int subdivisions) {
  std::string points, connectivity, offsets, types;
  std::vector<std::string> values(fields.size());
  int n_points = 0, n_cells = 0, n_connectivity = 0;
  for (int c = 0; c < space.mesh().n_cells(); ++c) {
    const int k = subdivisions > 0 ? subdivisions : std::max(space.cell_degree(c), 1);
    const Subdivision pieces = subdivide(space.mesh().cell_type(c), k);
    const auto cell = assembly::tabulate_cell(space, c, pieces.points);
    const int first = n_points;
    for (int q = 0; q < cell.points.rows(); ++q)
      points += fmt::format("{:.17g} {:.17g} 0\n", cell.points(q, 0), cell.points(q, 1));
    for (std::size_t f = 0; f < fields.size(); ++f) {
      const Eigen::MatrixXd field = fields[f].evaluate(c, cell);
      for (int q = 0; q < field.rows(); ++q) {
        for (int j = 0; j < field.cols(); ++j) values[f] += fmt::format("{}{:.17g}", j ? " " : "", field(q, j));
        values[f] += "\n";
      }
    }
    n_points += static_cast<int>(cell.points.rows());
    for (const auto& piece : pieces.cells) {
      for (std::size_t v = 0; v < piece.size(); ++v)
        connectivity += fmt::format("{}{}", v ? " " : "", first + piece[v]);
      connectivity += "\n";
      n_connectivity += static_cast<int>(piece.size());
      offsets += fmt::format("{}\n", n_connectivity);
      types += fmt::format("{}\n", pieces.vtk_type);
      ++n_cells;
    }
  }
  AtomicFile file(path);
  auto& out = file.stream();
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n"
      << fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n_points, n_cells) << "<PointData>\n";
  for (std::size_t f = 0; f < fields.size(); ++f)
    out << fmt::format("<DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n",
                       fields[f].name, fields[f].components)
        << values[f] << "</DataArray>\n";
  out << "</PointData>\n"
      << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
      << points << "</DataArray>\n</Points>\n<Cells>\n"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n"
      << connectivity << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n"
      << offsets << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n"
      << types << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  file.commit();
}

namespace {

// The coefficients of u on one cell's shapes, shape (n_shapes, components); 0 where eliminated.
// `dof(scalar dof, component)` numbers u.
Eigen::MatrixXd cell_coefficients(const space::H1Space& space, int cell, const Eigen::VectorXd& u, int components,
                                  const std::function<int(int, int)>& dof) {
  const auto& shapes = space.cell_shapes(cell);
  Eigen::MatrixXd local = Eigen::MatrixXd::Zero(shapes.size(), components);
  for (std::size_t s = 0; s < shapes.size(); ++s)
    for (int k = 0; k < components; ++k)
      if (const int index = dof(shapes[s].dof, k); index >= 0) local(s, k) = u(index);
  return local;
}

}  // namespace

void write_vtu(const std::filesystem::path& path, const space::H1Space& space, const Eigen::VectorXd& u,
               int subdivisions) {
  write_vtu_fields(
      path, space,
      {{"u", 1,
        [&](int cell, const assembly::CellValues& values) {
          return Eigen::MatrixXd(values.values * cell_coefficients(space, cell, u, 1, [](int d, int) { return d; }));
        }}},
      subdivisions);
}

void write_elastic_vtu(const std::filesystem::path& path, const space::VectorSpace& vector_space,
                       const std::vector<assembly::Material>& materials, const Eigen::VectorXd& u) {
  const space::H1Space& space = vector_space.scalar();
  const auto dof = [&](int d, int c) { return vector_space.dof(d, c); };
  auto displacement = [&](int cell, const assembly::CellValues& values) {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(values.values.rows(), 3);
    out.leftCols(2) = values.values * cell_coefficients(space, cell, u, 2, dof);
    return out;
  };
  auto von_mises = [&](int cell, const assembly::CellValues& values) {
    const Eigen::MatrixXd local = cell_coefficients(space, cell, u, 2, dof);
    const Eigen::MatrixXd dx = values.grad_x * local, dy = values.grad_y * local;  // columns: components
    const auto& m = materials[cell];
    Eigen::MatrixXd out(values.values.rows(), 1);
    for (Eigen::Index q = 0; q < out.rows(); ++q) {
      const double exx = dx(q, 0), eyy = dy(q, 1), exy = 0.5 * (dy(q, 0) + dx(q, 1));
      const double sxx = m.lambda * (exx + eyy) + 2 * m.mu * exx, syy = m.lambda * (exx + eyy) + 2 * m.mu * eyy;
      const double szz = m.out_of_plane * (exx + eyy), sxy = 2 * m.mu * exy;
      out(q, 0) = std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
                            3 * sxy * sxy);
    }
    return out;
  };
  write_vtu_fields(path, space, {{"displacement", 3, displacement}, {"von_mises", 1, von_mises}});
}

}  // namespace hpcontact::io
