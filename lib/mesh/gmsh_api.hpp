// The part of the Gmsh API that reading a mesh file needs, loaded on first use: libgmsh pulls in
// about 180 shared libraries (OpenCASCADE, FLTK, ...), which would cost every process 0.17 s of
// start-up if it were linked, while only scenes with a mesh file use it. The C API (gmshc.h) is
// resolved with dlopen/dlsym; outputs come back as std::vector.
#pragma once

#include <array>
#include <cstddef>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace hpcontact::mesh::gmsh_api {

struct ElementBlocks {
  std::vector<int> types;                       ///< one block per element type
  std::vector<std::vector<std::size_t>> tags;   ///< element tags per block
  std::vector<std::vector<std::size_t>> nodes;  ///< node tags per block, element after element
};

struct ElementType {
  std::string name;  ///< Gmsh's name, e.g. "Triangle 3", "Quadrilateral 9"
  int order = 1;
};

/// Exclusive use of Gmsh's one global model (loaded and initialized on first use, its terminal
/// output silenced) for the lifetime of the object.
/// @throws InputError if the Gmsh library cannot be loaded (naming the Debian package).
class Session {
 public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  /// Restarts Gmsh, so that every option is at its default (options outlive the model: one file's
  /// Mesh.MeshSizeFactor or recombination would mesh the next file too), and reads `path` into
  /// its model, so that a .geo's own options hold.
  /// @throws InputError with Gmsh's message (and restarts Gmsh, which ignores later files after
  /// an error inside a reader).
  void open(const std::string& path);
  /// Meshes the geometry read by open() (a .geo file) into first-order cells: Gmsh's
  /// frontal-Delaunay triangulation (Mesh.Algorithm = 6, Mesh.ElementOrder = 1: curved sides are
  /// taken from the geometry, see curve_points), with `quadrilaterals` recombined and every
  /// triangle left split into quadrilaterals (Mesh.RecombineAll = 1, Mesh.SubdivisionAlgorithm =
  /// 1), else kept as triangles (both options 0); elements at most `max_size` (Mesh.MeshSizeMax)
  /// before any split when given. @throws InputError with Gmsh's message.
  void generate(const std::string& path, std::optional<double> max_size, bool quadrilaterals);
  /// Meshes the geometry read by open() in 3-D with the .geo's own options (its Transfinite,
  /// Recombine and Mesh.SubdivisionAlgorithm settings decide the cells), elements at most
  /// `max_size` (Mesh.MeshSizeMax) when given. @throws InputError with Gmsh's message.
  void generate_volume(const std::string& path, std::optional<double> max_size);
  /// The model's bounding box: x_min, y_min, z_min, x_max, y_max, z_max.
  std::array<double, 6> bounding_box() const;
  int dimension() const;
  /// Elements of dimension `dim` on entity `tag` (-1: all).
  ElementBlocks elements(int dim, int tag = -1) const;
  /// Every node's tag and coordinates (x, y, z per node).
  void nodes(std::vector<std::size_t>& tags, std::vector<double>& coordinates) const;
  ElementType element_type(int type) const;
  /// (dim, tag) of the physical groups of dimension `dim`.
  std::vector<std::pair<int, int>> physical_groups(int dim) const;
  std::string physical_name(int dim, int tag) const;
  std::vector<int> entities_of_physical_group(int dim, int tag) const;
  /// Tags of the model's curves (entities of dimension 1).
  std::vector<int> curves() const;
  /// Gmsh's type of curve `tag`: "Line", "Circle", "Ellipse", "BSpline", "Discrete curve", ...
  std::string curve_type(int tag) const;
  /// The parameter on curve `tag` of each mesh node on it, its end points included: the parameters
  /// the mesher placed them at (exact, where projecting a node back onto the curve is accurate only
  /// to ~1e-9).
  std::unordered_map<std::size_t, double> curve_node_parameters(int tag) const;
  /// The points (x, y, z per point) of curve `tag` at the given parameters: the exact geometry.
  std::vector<double> curve_points(int tag, const std::vector<double>& parameters) const;

 private:
  std::unique_lock<std::mutex> lock_;
};

}  // namespace hpcontact::mesh::gmsh_api
