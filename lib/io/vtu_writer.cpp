// vtu_grid, vtu_text and the scalar and elastic fields written through them.
#include "io/vtu_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <optional>

#include "io/vtk_lagrange_nodes.hpp"
#include "io/vtk_xml_document.hpp"

namespace hpcontact::io {
namespace {

// The nodes of one reference cell's Lagrange cell: VTK order, reference points, entities.
struct NodePattern {
  assembly::ReferencePoints points;
  std::vector<LatticeEntity> entities;
};

// The order-k cell's lattice cut into linear triangles, as local node numbers (VTK's order): two
// per lattice square of a quadrilateral; the upward and downward triangles of a triangle.
std::vector<std::vector<int>> lattice_triangles(mesh::CellType type, int k) {
  const auto lattice = vtk_lagrange_lattice(type, k);
  std::map<std::array<int, 2>, int> local;
  for (std::size_t n = 0; n < lattice.size(); ++n) local[lattice[n]] = static_cast<int>(n);
  auto at = [&](int i, int j) { return local.at({i, j}); };
  std::vector<std::vector<int>> out;
  const bool quadrilateral = type == mesh::CellType::quadrilateral;
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k - (quadrilateral ? 0 : j); ++i) {
      if (quadrilateral) {
        out.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        out.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        continue;
      }
      out.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + j + 2 <= k) out.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return out;
}

NodePattern node_pattern(mesh::CellType type, int k) {
  const auto lattice = vtk_lagrange_lattice(type, k);
  NodePattern out{lattice_reference_points(lattice, k), {}};
  for (const auto& node : lattice) out.entities.push_back(lattice_entity(type, node, k));
  return out;
}

// Shares the points of vertices and edges between the cells that meet there: a vertex is keyed
// by its number, an edge node by its edge's vertices (smaller first) and its steps from the
// smaller one, so that both cells of an edge find the same point whatever their edge directions.
class SharedPoints {
 public:
  /// @param components of each point field summed at the points.
  SharedPoints(int k, std::vector<int> components)
      : sums(components.size()), k_(k), components_(std::move(components)) {}

  int index(mesh::CellType type, const LatticeEntity& entity, std::span<const int> cell_vertices) {
    if (entity.kind == LatticeEntity::Kind::interior) return add();
    std::array<long long, 3> key;
    if (entity.kind == LatticeEntity::Kind::vertex) {
      key = {-1, cell_vertices[entity.local], 0};
    } else {
      const auto [a, b] = mesh::local_edge_vertices(type, entity.local);
      const int va = cell_vertices[a], vb = cell_vertices[b];
      key = {std::min(va, vb), std::max(va, vb), va < vb ? entity.step : k_ - entity.step};
    }
    const auto [it, inserted] = keyed_.try_emplace(key, -1);
    if (inserted) it->second = add();
    return it->second;
  }

  std::vector<double> xyz;                // 3 per point
  std::vector<int> counts;                // cells that met at each point
  std::vector<std::vector<double>> sums;  // per field: its components per point

 private:
  int add() {
    xyz.insert(xyz.end(), {0.0, 0.0, 0.0});
    counts.push_back(0);
    for (std::size_t f = 0; f < sums.size(); ++f) sums[f].resize(sums[f].size() + components_[f], 0.0);
    return static_cast<int>(counts.size()) - 1;
  }
  int k_;
  std::vector<int> components_;
  std::map<std::array<long long, 3>, int> keyed_;
};

}  // namespace

VtuGrid vtu_grid(const space::H1Space& space, const std::vector<VtuField>& fields, int order,
                 const assembly::LocalRows& cells) {
  const auto& mesh = space.mesh();
  // The whole space's largest degree, also on a rank's part: every piece at the same order.
  const int k = order > 0 ? order : std::max(1, space.max_degree());
  std::optional<NodePattern> patterns[2];
  std::vector<int> components;
  for (const auto& field : fields) components.push_back(field.components);
  SharedPoints points(k, components);
  VtuGrid grid;
  auto& [xyz, connectivity, offsets, types, degrees, point_data, triangles] = grid;
  std::vector<std::vector<int>> lattice_cells[2];  // per type: triangles of local nodes
  for (int c = 0; c < mesh.n_cells(); ++c) {
    if (!cells.holds(c)) continue;
    const mesh::CellType type = mesh.cell_type(c);
    auto& pattern = patterns[static_cast<int>(type)];
    if (!pattern) {
      pattern = node_pattern(type, k);
      lattice_cells[static_cast<int>(type)] = lattice_triangles(type, k);
    }
    const auto first = static_cast<std::int64_t>(connectivity.size());
    const auto values = assembly::tabulate_cell(space, c, pattern->points);
    std::vector<Eigen::MatrixXd> field_values;
    for (const auto& field : fields) field_values.push_back(field.evaluate(c, values));
    for (int n = 0; n < pattern->points.size(); ++n) {
      const int p = points.index(type, pattern->entities[n], mesh.cell(c));
      if (points.counts[p] == 0) {
        points.xyz[3 * p] = values.points(n, 0);
        points.xyz[3 * p + 1] = values.points(n, 1);
      }
      ++points.counts[p];
      for (std::size_t f = 0; f < fields.size(); ++f) {
        const int m = fields[f].components;
        for (int j = 0; j < m; ++j) points.sums[f][m * p + j] += field_values[f](n, j);
      }
      connectivity.push_back(p);
    }
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    types.push_back(static_cast<std::uint8_t>(vtk_lagrange_cell_type(type)));
    degrees.push_back(space.cell_degree(c));
    for (const auto& local : lattice_cells[static_cast<int>(type)])
      triangles.push_back(
          {connectivity[first + local[0]], connectivity[first + local[1]], connectivity[first + local[2]]});
  }
  const std::size_t n_points = points.counts.size();
  for (std::size_t f = 0; f < fields.size(); ++f) {
    auto& sums = points.sums[f];
    const int m = fields[f].components;
    for (std::size_t p = 0; p < n_points; ++p)
      for (int j = 0; j < m; ++j) sums[m * p + j] /= points.counts[p];
  }

  xyz = std::move(points.xyz);
  for (std::size_t f = 0; f < fields.size(); ++f)
    point_data.push_back({fields[f].name, fields[f].components, std::move(points.sums[f])});
  return grid;
}

std::string vtu_text(const VtuGrid& grid) {
  VtkXmlDocument document("UnstructuredGrid");
  std::string piece = fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n<PointData>\n", grid.n_points(),
                                  grid.types.size());
  for (const auto& array : grid.point_data) piece += document.array(array.name, array.values, array.components);
  piece += "</PointData>\n<CellData>\n" + document.array("p", grid.degrees) + "</CellData>\n<Points>\n" +
           document.array("Points", grid.xyz, 3) + "</Points>\n<Cells>\n" +
           document.array("connectivity", grid.connectivity) + document.array("offsets", grid.offsets) +
           document.array("types", grid.types) + "</Cells>\n</Piece>\n";
  return document.text(piece);
}

VtuGrid solution_vtu_grid(const assembly::CellField& u) {
  const auto names = solution_vtu_fields();  // (the PVTU names the same)
  return vtu_grid(*u.space,
                  {{names[0].first, names[0].second,
                    [&](int cell, const assembly::CellValues& values) {
                      return Eigen::MatrixXd(values.values * u.coefficients(cell));
                    }},
                   {names[1].first, names[1].second,
                    [&](int cell, const assembly::CellValues& values) {
                      const Eigen::MatrixXd local = u.coefficients(cell);
                      Eigen::MatrixXd out = Eigen::MatrixXd::Zero(values.values.rows(), 3);
                      out.col(0) = values.grad_x * local;
                      out.col(1) = values.grad_y * local;
                      return out;
                    }}},
                  0, u.rows);
}

VtuGrid elastic_vtu_grid(const assembly::CellField& u, const std::vector<assembly::Material>& materials) {
  auto displacement = [&](int cell, const assembly::CellValues& values) {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(values.values.rows(), 3);
    out.leftCols(2) = values.values * u.coefficients(cell);
    return out;
  };
  // σ = λ tr(ε) I + 2μ ε in the plane, σ_zz of the plane model: columns xx, yy, zz, xy (yz = xz = 0).
  auto stress = [&](int cell, const assembly::CellValues& values) {
    const Eigen::MatrixXd local = u.coefficients(cell);
    const Eigen::MatrixXd dx = values.grad_x * local, dy = values.grad_y * local;  // columns: components
    const auto& m = materials[cell];
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(values.values.rows(), 6);
    for (Eigen::Index q = 0; q < out.rows(); ++q) {
      const auto s = assembly::plane_stress_of(m, dx(q, 0), dy(q, 1), 0.5 * (dy(q, 0) + dx(q, 1)));
      for (int c = 0; c < 4; ++c) out(q, c) = s[static_cast<std::size_t>(c)];
    }
    return out;
  };
  auto von_mises = [&](int cell, const assembly::CellValues& values) {
    const Eigen::MatrixXd s = stress(cell, values);
    Eigen::MatrixXd out(values.values.rows(), 1);
    for (Eigen::Index q = 0; q < out.rows(); ++q)
      out(q, 0) = assembly::von_mises_of({s(q, 0), s(q, 1), s(q, 2), s(q, 3)});
    return out;
  };
  const auto names = elastic_vtu_fields();  // (the PVTU names the same)
  return vtu_grid(*u.space,
                  {{names[0].first, names[0].second, displacement},
                   {names[1].first, names[1].second, stress},
                   {names[2].first, names[2].second, von_mises}},
                  0, u.rows);
}

std::vector<std::pair<std::string, int>> solution_vtu_fields() { return {{"u", 1}, {"grad_u", 3}}; }
std::vector<std::pair<std::string, int>> elastic_vtu_fields() {
  return {{"displacement", 3}, {"stress", 6}, {"von_mises", 1}};
}

std::string pvtu_text(const std::vector<std::string>& pieces, const std::vector<std::pair<std::string, int>>& fields) {
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "<PUnstructuredGrid GhostLevel=\"0\">\n<PPointData>\n";
  for (const auto& [name, components] : fields)
    out += fmt::format("<PDataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\"/>\n", name, components);
  out +=
      "</PPointData>\n<PCellData>\n<PDataArray type=\"Int32\" Name=\"p\" NumberOfComponents=\"1\"/>\n</PCellData>\n"
      "<PPoints>\n<PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n</PPoints>\n";
  for (const auto& piece : pieces) out += fmt::format("<Piece Source=\"{}\"/>\n", piece);
  return out + "</PUnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace hpcontact::io
