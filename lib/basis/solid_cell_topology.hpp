// Local numbering of the reference hexahedron [-1, 1]³ and tetrahedron (−1,−1,−1), (1,−1,−1),
// (−1,1,−1), (−1,−1,1): their vertices, edges and faces, shared by bases, meshes and spaces.
#pragma once

#include <array>

namespace hpcontact::basis {

/// The two kinds of cells of a solid mesh (one kind per mesh: a conforming mesh mixing them needs
/// pyramids between a hexahedron's square faces and tetrahedra's triangles).
enum class SolidCellKind : unsigned char { hexahedron, tetrahedron };

/// Hexahedron, tensor ordered: vertex v = a + 2b + 4c sits at (2a − 1, 2b − 1, 2c − 1). Local
/// edge e runs along axis e / 4 from its lower to its upper local vertex (kHexEdgeVertices).
/// Local face f lies at coordinate f % 2 == 0 ? −1 : +1 of axis f / 2; its vertices are listed
/// in the tensor order of its two free axes (kHexFaceAxes: the lower axis first).
inline constexpr std::array<std::array<int, 2>, 12> kHexEdgeVertices{
    {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
inline constexpr std::array<std::array<int, 4>, 6> kHexFaceVertices{
    {{0, 2, 4, 6}, {1, 3, 5, 7}, {0, 1, 4, 5}, {2, 3, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}}};
inline constexpr std::array<std::array<int, 2>, 6> kHexFaceAxes{{{1, 2}, {1, 2}, {0, 2}, {0, 2}, {0, 1}, {0, 1}}};

/// Tetrahedron: local edges as vertex pairs in ascending order; face f opposite vertex f, its
/// vertices ascending. A mesh lists each tetrahedron's vertices in ascending global numbers, so
/// every local edge and face runs as its global one.
inline constexpr std::array<std::array<int, 2>, 6> kTetEdgeVertices{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};
inline constexpr std::array<std::array<int, 3>, 4> kTetFaceVertices{{{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}}};

}  // namespace hpcontact::basis
