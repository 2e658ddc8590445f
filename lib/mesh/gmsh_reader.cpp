// read_gmsh_mesh: a line-based parser of the MSH 4.x ASCII sections that a 2-D quadrilateral mesh
// needs ($MeshFormat, $PhysicalNames, $Entities, $Nodes, $Elements); other sections are skipped.
#include "mesh/gmsh_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/error.hpp"

namespace hpcontact::mesh {
namespace {

using Tag = long long;

/// One non-blank line of the file split into fields; a quoted name ("top wall") is one field.
struct Line {
  std::vector<std::string> fields;
  int number = 0;
};

/// A 2-node line element on a curve, kept until the quadrilateral mesh and its edges exist.
struct LineElement {
  std::string tag;
  Tag curve;
  std::array<Tag, 2> nodes;
  int line;
};

/// Twice the signed area of the polygon cell (positive if counterclockwise).
double twice_signed_area(const std::vector<Point>& vertices, const std::array<int, 4>& cell) {
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Point& a = vertices[cell[k]];
    const Point& b = vertices[cell[(k + 1) % 4]];
    sum += a.x() * b.y() - b.x() * a.y();
  }
  return sum;
}

class MshParser {
 public:
  explicit MshParser(const std::string& path) : path_(path), in_(path) {
    if (!in_) throw InputError(path + ": cannot open the Gmsh mesh file for reading");
  }

  QuadMesh parse();

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw InputError(path_ + ":" + std::to_string(line) + ": " + what);
  }
  std::optional<Line> next_line();
  Line line_in(const std::string& section);
  void expect_end(const std::string& section);
  void skip_section(const std::string& section);
  const std::string& field(const Line& line, std::size_t i) const;
  Tag integer(const Line& line, std::size_t i) const;
  double real(const Line& line, std::size_t i) const;
  Tag node_tag(const Line& line, std::size_t i) const;
  void add_node(Tag tag, const Point& point, int line);

  void read_format();
  void read_physical_names();
  void read_entities();
  void read_nodes();
  void read_elements();
  QuadMesh build_mesh() const;

  std::string path_;
  std::ifstream in_;
  int line_number_ = 0;
  bool msh40_ = false;                               // 4.0 lays out nodes and blocks unlike 4.1
  std::map<Tag, std::string> curve_group_names_;     // dimension-1 physical tag -> name
  std::map<Tag, std::vector<Tag>> curve_groups_;     // curve entity tag -> its physical tags
  std::vector<std::pair<Tag, Point>> nodes_;         // in file order
  std::unordered_map<Tag, std::size_t> node_index_;  // node tag -> position in nodes_
  std::vector<std::array<Tag, 4>> quads_;
  std::vector<LineElement> lines_;
};

std::optional<Line> MshParser::next_line() {
  std::string text;
  while (std::getline(in_, text)) {
    Line line{{}, ++line_number_};
    std::size_t pos = 0;
    while ((pos = text.find_first_not_of(" \t\r", pos)) != std::string::npos) {
      std::size_t end;
      if (text[pos] == '"') {
        end = text.find('"', pos + 1);
        if (end == std::string::npos) fail(line.number, "unterminated quoted name");
        line.fields.push_back(text.substr(pos + 1, end - pos - 1));
        ++end;
      } else {
        end = text.find_first_of(" \t\r", pos);
        line.fields.push_back(text.substr(pos, end - pos));
      }
      pos = end;
    }
    if (!line.fields.empty()) return line;
  }
  return std::nullopt;
}

Line MshParser::line_in(const std::string& section) {
  auto line = next_line();
  if (!line) fail(line_number_, "the file ends inside the " + section + " section (truncated?)");
  if (line->fields[0].starts_with('$'))
    fail(line->number, "the " + section + " section ends early at '" + line->fields[0] +
                           "': it holds fewer entries than its counts announce (truncated?)");
  return *line;
}

void MshParser::expect_end(const std::string& section) {
  const std::string end = "$End" + section.substr(1);
  const auto line = next_line();
  if (!line) fail(line_number_, "the file ends before " + end + " (truncated?)");
  if (line->fields[0] != end)
    fail(line->number, "expected " + end + ", found '" + line->fields[0] +
                           "': the section holds more entries than its counts announce");
}

void MshParser::skip_section(const std::string& section) {
  const std::string end = "$End" + section.substr(1);
  while (const auto line = next_line())
    if (line->fields[0] == end) return;
  fail(line_number_, "the file ends before " + end + " (truncated?)");
}

const std::string& MshParser::field(const Line& line, std::size_t i) const {
  if (i >= line.fields.size())
    fail(line.number,
         "expected at least " + std::to_string(i + 1) + " fields, found " + std::to_string(line.fields.size()));
  return line.fields[i];
}

Tag MshParser::integer(const Line& line, std::size_t i) const {
  const std::string& text = field(line, i);
  Tag value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size())
    fail(line.number, "field " + std::to_string(i + 1) + " '" + text + "' is not an integer");
  return value;
}

double MshParser::real(const Line& line, std::size_t i) const {
  const std::string& text = field(line, i);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    fail(line.number, "field " + std::to_string(i + 1) + " '" + text + "' is not a finite number");
  return value;
}

Tag MshParser::node_tag(const Line& line, std::size_t i) const {
  const Tag tag = integer(line, i);
  if (!node_index_.contains(tag))
    fail(line.number,
         "element " + field(line, 0) + " refers to node tag " + std::to_string(tag) + ", which $Nodes does not define");
  return tag;
}

void MshParser::add_node(Tag tag, const Point& point, int line) {
  if (!node_index_.try_emplace(tag, nodes_.size()).second)
    fail(line, "node tag " + std::to_string(tag) + " is defined twice");
  nodes_.emplace_back(tag, point);
}

void MshParser::read_format() {
  const auto first = next_line();
  if (!first || first->fields[0] != "$MeshFormat")
    throw InputError(path_ + ": not a Gmsh MSH file: it must begin with $MeshFormat");
  const Line line = line_in("$MeshFormat");
  const double version = real(line, 0);
  if (!(version >= 4.0 && version < 5.0))
    fail(line.number,
         "MSH version " + field(line, 0) + " is not supported; only 4.0 and 4.1 are (export with gmsh -format msh41)");
  msh40_ = version < 4.05;  // Gmsh 4.0 writes "4" or "4.0"
  if (integer(line, 1) != 0) fail(line.number, "binary MSH files are not supported; save as ASCII (gmsh -bin 0)");
  expect_end("$MeshFormat");
}

void MshParser::read_physical_names() {
  const Tag n_names = integer(line_in("$PhysicalNames"), 0);
  for (Tag k = 0; k < n_names; ++k) {
    const Line line = line_in("$PhysicalNames");  // dimension, tag, "name"
    if (integer(line, 0) == 1) curve_group_names_[integer(line, 1)] = field(line, 2);
  }
  expect_end("$PhysicalNames");
}

void MshParser::read_entities() {
  const Line counts = line_in("$Entities");
  const Tag n_points = integer(counts, 0), n_curves = integer(counts, 1);
  for (Tag k = 0; k < n_points; ++k) line_in("$Entities");
  for (Tag k = 0; k < n_curves; ++k) {
    // tag, bounding box (6 numbers), number of physical tags, physical tags, bounding points
    const Line line = line_in("$Entities");
    const Tag n_groups = integer(line, 7);
    auto& groups = curve_groups_[integer(line, 0)];
    for (Tag g = 0; g < n_groups; ++g) groups.push_back(integer(line, 8 + g));
  }
  // Surfaces and volumes carry no boundary labels.
  skip_section("$Entities");
}

void MshParser::read_nodes() {
  const Tag n_blocks = integer(line_in("$Nodes"), 0);
  for (Tag b = 0; b < n_blocks; ++b) {
    const Tag n_nodes = integer(line_in("$Nodes"), 3);
    if (msh40_) {
      for (Tag k = 0; k < n_nodes; ++k) {  // "tag x y z"
        const Line line = line_in("$Nodes");
        add_node(integer(line, 0), Point(real(line, 1), real(line, 2)), line.number);
      }
      continue;
    }
    // 4.1: all tags of the block, then all coordinates "x y z [parametric u v]".
    std::vector<Tag> tags;
    for (Tag k = 0; k < n_nodes; ++k) tags.push_back(integer(line_in("$Nodes"), 0));
    for (Tag tag : tags) {
      const Line line = line_in("$Nodes");
      add_node(tag, Point(real(line, 0), real(line, 1)), line.number);
    }
  }
  expect_end("$Nodes");
}

void MshParser::read_elements() {
  const Tag n_blocks = integer(line_in("$Elements"), 0);
  for (Tag b = 0; b < n_blocks; ++b) {
    // 4.1: "entityDim entityTag type count"; 4.0 swaps the first two.
    const Line block = line_in("$Elements");
    const Tag dim = integer(block, msh40_ ? 1 : 0), entity = integer(block, msh40_ ? 0 : 1);
    const Tag type = integer(block, 2), n_elements = integer(block, 3);
    if (dim == 2 && type != 3)
      fail(block.number, "only 4-node quadrilaterals (type 3) are supported; found type " + std::to_string(type));
    if (dim == 1 && type != 1)
      fail(block.number, "only 2-node lines (type 1) are supported on curves; found type " + std::to_string(type));
    for (Tag k = 0; k < n_elements; ++k) {
      const Line line = line_in("$Elements");  // "tag node node ..."
      if (dim == 2)
        quads_.push_back({node_tag(line, 1), node_tag(line, 2), node_tag(line, 3), node_tag(line, 4)});
      else if (dim == 1)
        lines_.push_back({line.fields[0], entity, {node_tag(line, 1), node_tag(line, 2)}, line.number});
      // Point elements (type 15) and 3-D elements say nothing about a 2-D quadrilateral mesh.
    }
  }
  expect_end("$Elements");
}

QuadMesh MshParser::build_mesh() const {
  if (quads_.empty())
    throw InputError(path_ +
                     ": no 4-node quadrilaterals (type 3) in $Elements; if the model has physical "
                     "groups, put the surface in one too (or save with Mesh.SaveAll = 1)");

  // Only nodes of quadrilaterals become vertices (kept in file order): geometry points that no
  // cell uses would be isolated vertices without any basis function support.
  std::vector<bool> used(nodes_.size(), false);
  for (const auto& quad : quads_)
    for (Tag tag : quad) used[node_index_.at(tag)] = true;
  std::vector<Point> vertices;
  std::unordered_map<Tag, int> vertex_of;
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    if (used[k]) {
      vertex_of[nodes_[k].first] = static_cast<int>(vertices.size());
      vertices.push_back(nodes_[k].second);
    }

  std::vector<std::array<int, 4>> cells;
  for (const auto& quad : quads_) {
    std::array<int, 4> cell;
    for (int k = 0; k < 4; ++k) cell[k] = vertex_of.at(quad[k]);
    // Gmsh orders nodes along the surface orientation, which may be clockwise in the plane.
    if (twice_signed_area(vertices, cell) < 0.0) std::swap(cell[1], cell[3]);
    cells.push_back(cell);
  }
  QuadMesh mesh(std::move(vertices), std::move(cells), path_);

  std::map<std::pair<int, int>, int> boundary_edge;  // (lower, higher vertex) -> edge
  for (int e : mesh.boundary_edges()) boundary_edge[{mesh.edge(e)[0], mesh.edge(e)[1]}] = e;
  for (const LineElement& line : lines_) {
    const auto groups = curve_groups_.find(line.curve);
    if (groups == curve_groups_.end() || groups->second.empty()) continue;  // no label
    // A label decides the boundary condition, so an edge in two groups would be ambiguous.
    if (groups->second.size() > 1)
      fail(line.line, "curve " + std::to_string(line.curve) + " belongs to " + std::to_string(groups->second.size()) +
                          " physical groups; a boundary edge can carry only one label");
    const Tag group = groups->second.front();
    const auto name = curve_group_names_.find(group);
    const std::string label = name != curve_group_names_.end() ? name->second : std::to_string(group);

    const auto a = vertex_of.find(line.nodes[0]), b = vertex_of.find(line.nodes[1]);
    auto edge = boundary_edge.end();
    if (a != vertex_of.end() && b != vertex_of.end()) edge = boundary_edge.find(std::minmax(a->second, b->second));
    if (edge == boundary_edge.end())
      fail(line.line, "line element " + line.tag + " (nodes " + std::to_string(line.nodes[0]) + ", " +
                          std::to_string(line.nodes[1]) + ") of physical group '" + label +
                          "' is not a boundary edge of the quadrilateral mesh");
    mesh.set_edge_label(edge->second, label);
  }
  return mesh;
}

QuadMesh MshParser::parse() {
  read_format();
  bool has_nodes = false, has_elements = false;
  while (const auto line = next_line()) {
    const std::string& section = line->fields[0];
    if (section == "$PhysicalNames") {
      read_physical_names();
    } else if (section == "$Entities") {
      read_entities();
    } else if (section == "$Nodes") {
      read_nodes();
      has_nodes = true;
    } else if (section == "$Elements") {
      read_elements();  // Gmsh writes $Nodes first, so node tags are known here
      has_elements = true;
    } else if (section.starts_with('$')) {
      skip_section(section);
    } else {
      fail(line->number, "expected a section header such as $Nodes, found '" + section + "'");
    }
  }
  if (!has_nodes || !has_elements)
    throw InputError(path_ + ": no " + (has_nodes ? "$Elements" : "$Nodes") +
                     " section; a Gmsh mesh file needs both $Nodes and $Elements");
  return build_mesh();
}

}  // namespace

QuadMesh read_gmsh_mesh(const std::string& path) { return MshParser(path).parse(); }

}  // namespace hpcontact::mesh
