// Local refinement of a 2-D mesh for adaptivity: red refinement of chosen cells (each into four),
// kept 1-irregular, and a conforming closure of the hanging midpoints by triangles, so that the
// mesh an adaptive step hands on is an ordinary conforming Mesh (mixed quadrilaterals and
// triangles) and every solver, coupling and output works on it unchanged.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

/// The leaves of a red-refinement forest over a coarse mesh, and the conforming mesh they close to.
///
/// Red refinement splits a quadrilateral at its edge midpoints and its centre, a triangle at its
/// edge midpoints. A leaf whose edge carries a neighbour's midpoint has a hanging node there; the
/// forest is kept 1-irregular (no edge of a leaf carries midpoints two levels deep) and no leaf has
/// more than one hanging edge: leaves that would are refined red too. A leaf with one hanging edge
/// is closed by triangles through the midpoint: a quadrilateral q0 q1 q2 q3 hanging at m on q0 q1 by
/// q0 m q3, m q1 q2, m q2 q3; a triangle by its bisection at m. Closure cells are never refined:
/// the next refinement splits their leaf red and closes afresh (red–green refinement), so cell
/// shapes stay those of the coarse mesh's red children (minimum angle bounded).
///
/// Straight cells only: a blended (curved) cell's closure triangles would be curved triangles,
/// which T_h does not support.
class AdaptiveMesh {
 public:
  /// The coarse cells as the leaves (`coarse` is copied). @throws InputError naming `origin` if
  /// `coarse` has curved cells or is a part of a mesh.
  AdaptiveMesh(const Mesh& coarse, const std::string& origin);

  int n_leaves() const { return static_cast<int>(leaves_.size()); }
  /// Red-refinement generation of a leaf (0: a coarse cell).
  int level(int leaf) const { return leaves_[leaf].level; }
  /// The coarse cell a leaf lies in.
  int coarse_cell(int leaf) const { return leaves_[leaf].coarse_cell; }

  /// Splits the leaves `marked` red, then the leaves that 1-irregularity and the closure rule
  /// (one hanging edge at most) need. Returns, for each new leaf, the leaf (numbered before the
  /// call) it lies in: what carries degrees and indicators over. @throws InputError naming the
  /// origin if a mark is not a leaf.
  std::vector<int> refine(const std::vector<int>& marked);

  /// The conforming mesh: every leaf, a hanging one as its closure triangles. Boundary labels and
  /// parts are those of the coarse edge each boundary edge lies on. `leaf_of_cell`, if given,
  /// receives each cell's leaf.
  Mesh conforming_mesh(std::vector<int>* leaf_of_cell = nullptr) const;

 private:
  struct Leaf {
    std::array<int, 4> vertices;  ///< counterclockwise; a triangle's fourth is -1
    /// The coarse edge each side lies on (side k from vertex k to k + 1), -1 inside a coarse cell.
    std::array<int, 4> side_origin;
    int level = 0;
    int coarse_cell = 0;
    int size() const { return vertices[3] < 0 ? 3 : 4; }
  };
  /// The midpoint of segment a–b if some leaf was split across it, else -1.
  int midpoint(int a, int b) const;
  int make_midpoint(int a, int b);
  /// The side of `leaf` carrying a midpoint, -1 if none; -2 if it has more than one or one carries
  /// midpoints two levels deep (the leaf must be split).
  int hanging_side(const Leaf& leaf) const;
  /// Appends leaf's four red children to `out`.
  void split(const Leaf& leaf, std::vector<Leaf>& out);

  Mesh coarse_;  ///< for the labels and parts of its boundary edges
  std::string origin_;
  std::vector<Point> vertices_;
  std::vector<Leaf> leaves_;
  std::unordered_map<std::uint64_t, int> midpoints_;  ///< key: the segment's ends, lower first
};

}  // namespace hpcontact::mesh
