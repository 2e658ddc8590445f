// Local cuts of the cells on Γ_C that make chosen points of Γ_C vertices with disjoint stars, so
// that grade_towards_vertices (mesh/point_grading.hpp) can grade towards each of them. Refining the
// whole mesh uniformly does the same where the points are one edge apart or inside edges, at four
// times the cells everywhere; these cuts touch only the cells with an edge on Γ_C and leave every
// other edge of the mesh whole, so the rest of the mesh is unchanged.
#pragma once

#include <optional>
#include <vector>

#include "mesh/mesh.hpp"

namespace hpcontact::mesh {

struct SeparatedMesh {
  Mesh mesh;
  std::vector<int> parents;  ///< the input cell each output cell lies in
};

/// `points`: arc lengths on Γ_C (mesh/contact_boundary.hpp). Every edge of Γ_C that holds a point
/// inside it, or a point at each end, gets those points as vertices, and midpoints between
/// consecutive points of the edge (ends included) as separators; its cell is cut into a fan of
/// triangles from the vertices off that edge (a quadrilateral a b y x, with a b on Γ_C: the
/// triangles of a … w_j on x, then w_j y x, then w_j … b on y). Each triangle then holds at most
/// one of the points on its edge. Cells without such an edge come first and are kept as they are.
/// Returns nothing where the cuts cannot be made locally: a cell to cut is curved, or has two edges
/// to cut. Whether the stars are then disjoint (cells with points at vertices off Γ_C) is for the
/// caller to check.
std::optional<SeparatedMesh> separate_contact_points(const Mesh& mesh, const std::vector<double>& points);

}  // namespace hpcontact::mesh
