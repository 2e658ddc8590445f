// Mesh::pack / unpack and BlendedGeometry::pack / unpack: every table copied as it is (no topology
// rebuilt, no curve resampled), so that the mesh a rank receives is the sender's to the bit.
#include "core/byte_buffer.hpp"
#include "mesh/blended_geometry.hpp"
#include "mesh/edge_curve.hpp"
#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

void put_points(ByteWriter& out, const std::vector<Point>& points) {
  std::vector<double> coordinates;
  coordinates.reserve(2 * points.size());
  for (const auto& x : points) coordinates.insert(coordinates.end(), {x.x(), x.y()});
  out.put(coordinates);
}

std::vector<Point> get_points(ByteReader& in) {
  const auto coordinates = in.get_vector<double>();
  HPC_VERIFY(coordinates.size() % 2 == 0, "a point list of an odd number of coordinates");
  std::vector<Point> points;
  points.reserve(coordinates.size() / 2);
  for (std::size_t k = 0; k < coordinates.size(); k += 2) points.emplace_back(coordinates[k], coordinates[k + 1]);
  return points;
}

namespace {

using CurveList = std::vector<std::shared_ptr<const EdgeCurve>>;

std::shared_ptr<const EdgeCurve> get_curve(ByteReader& in, const CurveList& curves) {
  const auto number = in.get<std::int32_t>();
  HPC_VERIFY(number >= -1 && number < static_cast<std::int64_t>(curves.size()), "a curve number out of range");
  return number < 0 ? nullptr : curves[static_cast<std::size_t>(number)];
}

}  // namespace

std::int32_t CurveTable::number_of(const EdgeCurve* curve) {
  if (!curve) return -1;
  const auto [at, added] = index.emplace(curve, static_cast<std::int32_t>(curves.size()));
  if (added) curves.push_back(curve);
  return at->second;
}

void BlendedGeometry::pack(ByteWriter& out, CurveTable& curves) const {
  out.put(type_);
  put_points(out, {corners_.begin(), corners_.end()});
  for (const auto& side : sides_) {
    out.put(curves.number_of(side.curve.get()));
    out.put(static_cast<char>(side.reversed));
    out.put(curves.number_of(side.quotient.get()));
  }
  out.put(static_cast<char>(part_.has_value()));
  if (part_)
    out.put(std::vector<double>{part_->matrix(0, 0), part_->matrix(1, 0), part_->matrix(0, 1), part_->matrix(1, 1),
                                part_->offset.x(), part_->offset.y()});
}

BlendedGeometry BlendedGeometry::unpack(ByteReader& in, const CurveList& curves) {
  const auto type = in.get<CellType>();
  const auto corners = get_points(in);
  HPC_VERIFY(corners.size() == 4, "a cell map without its four corners");
  BlendedGeometry geometry(type, {corners[0], corners[1], corners[2], corners[3]});
  for (auto& side : geometry.sides_) {
    side.curve = get_curve(in, curves);
    side.reversed = in.get<char>() != 0;
    side.quotient = get_curve(in, curves);
  }
  if (in.get<char>()) {
    const auto numbers = in.get_vector<double>();
    HPC_VERIFY(numbers.size() == 6, "a child's map without its matrix and offset");
    Part part;
    part.matrix << numbers[0], numbers[2], numbers[1], numbers[3];
    part.offset = Eigen::Vector2d(numbers[4], numbers[5]);
    geometry.part_ = part;
  }
  return geometry;
}

void Mesh::pack(ByteWriter& out) const {
  put_points(out, vertices_);
  out.put(cells_);
  out.put(edges_);
  out.put(cell_edges_);
  out.put(cell_edge_signs_);
  out.put(edge_cells_);
  out.put(boundary_edges_);
  out.put(static_cast<std::uint64_t>(labels_.size()));
  for (const auto& label : labels_) out.put(label);
  out.put(edge_label_index_);
  out.put(edge_parts_);
  // The maps name their curves by number, so the table of distinct curves (known once every map
  // is written) goes first and the maps after it, as one block of bytes.
  CurveTable table;
  ByteWriter maps;
  maps.put(static_cast<std::uint64_t>(cell_geometry_.size()));
  for (const auto& geometry : cell_geometry_) {
    maps.put(static_cast<char>(geometry != nullptr));
    if (geometry) geometry->pack(maps, table);
  }
  out.put(static_cast<std::uint64_t>(table.curves.size()));
  for (const EdgeCurve* curve : table.curves) put_points(out, curve->values());
  out.put(maps.take());
  out.put(global_cells_);
  out.put(global_vertices_);
  out.put(global_edges_);
}

Mesh Mesh::unpack(ByteReader& in) {
  Mesh mesh;
  mesh.vertices_ = get_points(in);
  mesh.cells_ = in.get_vector<std::array<int, 4>>();
  mesh.edges_ = in.get_vector<std::array<int, 2>>();
  mesh.cell_edges_ = in.get_vector<std::array<int, 4>>();
  mesh.cell_edge_signs_ = in.get_vector<std::array<std::int8_t, 4>>();
  mesh.edge_cells_ = in.get_vector<std::array<int, 2>>();
  mesh.boundary_edges_ = in.get_vector<int>();
  // (Each label and curve takes at least 8 bytes, each map at least 1: larger counts are corrupt.)
  mesh.labels_.resize(in.get_count(8));
  for (auto& label : mesh.labels_) label = in.get_string();
  mesh.edge_label_index_ = in.get_vector<std::uint16_t>();
  mesh.edge_parts_ = in.get_vector<BoundaryPart>();
  CurveList curves(in.get_count(8));
  for (auto& curve : curves) curve = std::make_shared<const EdgeCurve>(EdgeCurve::from_values(get_points(in)));
  const auto map_bytes = in.get_vector<char>();
  ByteReader maps(map_bytes);
  mesh.cell_geometry_.resize(maps.get_count(1));
  for (auto& geometry : mesh.cell_geometry_)
    if (maps.get<char>()) geometry = std::make_shared<const BlendedGeometry>(BlendedGeometry::unpack(maps, curves));
  HPC_VERIFY(maps.at_end(), "bytes of a mesh's cell maps left over");
  mesh.global_cells_ = in.get_vector<int>();
  mesh.global_vertices_ = in.get_vector<int>();
  mesh.global_edges_ = in.get_vector<int>();
  HPC_VERIFY(mesh.cells_.size() == mesh.cell_edges_.size() && mesh.edges_.size() == mesh.edge_cells_.size() &&
                 mesh.edge_parts_.size() == mesh.edges_.size() && !mesh.labels_.empty(),
             "a mesh's tables of different lengths");
  return mesh;
}

}  // namespace hpcontact::mesh
