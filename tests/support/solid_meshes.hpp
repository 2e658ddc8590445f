// Solid test meshes: a box mesh (hexahedra or tetrahedra) whose vertex numbers and cells' local
// vertex orders are shuffled (so that every orientation of shared edges and faces occurs), and a smoothly distorted
// one (trilinear, non-affine cells), and the §7 square extruded.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "mesh/solid_mesh.hpp"

namespace hpcontact::testing {

/// The 24 orientation-preserving symmetries of the reference hexahedron as vertex maps: entry
/// [s][v] is the local vertex that v becomes.
inline std::vector<std::array<int, 8>> hexahedron_rotations() {
  std::vector<std::array<int, 8>> out;
  std::array<int, 3> axes{0, 1, 2};
  do {
    // The parity of the axis permutation times that of the flips must be even.
    int inversions = 0;
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b) inversions += axes[a] > axes[b];
    for (int flips = 0; flips < 8; ++flips) {
      const int flip_parity = (flips & 1) + ((flips >> 1) & 1) + ((flips >> 2) & 1);
      if ((inversions + flip_parity) % 2 != 0) continue;
      std::array<int, 8> map{};
      for (int v = 0; v < 8; ++v) {
        int image = 0;
        for (int k = 0; k < 3; ++k) image |= (((v >> axes[k]) & 1) ^ ((flips >> k) & 1)) << k;
        map[v] = image;
      }
      out.push_back(map);
    }
  } while (std::next_permutation(axes.begin(), axes.end()));
  return out;
}

/// `box` with its vertices renumbered at random and each hexahedron's vertex list rotated by a
/// random symmetry: the same geometry and labels, every orientation of edges and faces (on
/// tetrahedra the renumbering alone gives every order of a cell's vertices).
inline mesh::SolidMesh shuffled(const mesh::SolidMesh& box, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<int> number(box.n_vertices());
  std::iota(number.begin(), number.end(), 0);
  std::shuffle(number.begin(), number.end(), random);
  std::vector<mesh::SolidPoint> vertices(box.n_vertices());
  for (int v = 0; v < box.n_vertices(); ++v) vertices[number[v]] = box.vertex(v);
  if (box.is_tetrahedral()) {
    std::vector<std::array<int, 4>> cells;
    for (int c = 0; c < box.n_cells(); ++c) {
      std::array<int, 4> cell{};
      for (int v = 0; v < 4; ++v) cell[v] = number[box.cell(c)[v]];
      std::shuffle(cell.begin(), cell.end(), random);
      cells.push_back(cell);
    }
    std::vector<std::pair<std::array<int, 4>, std::string>> labels;
    for (const auto& face : box.boundary_faces()) {
      std::array<int, 4> triangle{-1, -1, -1, -1};
      for (int k = 0; k < 3; ++k) triangle[k] = number[box.cell(face.cell)[mesh::kTetFaceVertices[face.local_face][k]]];
      labels.emplace_back(triangle, face.label);
    }
    return mesh::SolidMesh::tetrahedra(std::move(vertices), std::move(cells), "shuffled tetrahedra", labels);
  }
  const auto rotations = hexahedron_rotations();
  std::vector<std::array<int, 8>> cells;
  for (int c = 0; c < box.n_cells(); ++c) {
    const auto& rotation = rotations[random() % rotations.size()];
    std::array<int, 8> cell{};
    for (int v = 0; v < 8; ++v) cell[rotation[v]] = number[box.cell(c)[v]];
    cells.push_back(cell);
  }
  std::vector<std::pair<std::array<int, 4>, std::string>> labels;
  for (const auto& face : box.boundary_faces()) {
    std::array<int, 4> quad{};
    for (int k = 0; k < 4; ++k) quad[k] = number[box.cell(face.cell)[mesh::kHexFaceVertices[face.local_face][k]]];
    labels.emplace_back(quad, face.label);
  }
  return mesh::SolidMesh(std::move(vertices), std::move(cells), "shuffled box", labels);
}

/// The unit-cube mesh with interior vertices moved by a smooth map that fixes the boundary:
/// x + δ sin(πx) sin(πy) sin(πz)·(1, −1, 1) (non-affine trilinear cells).
inline mesh::SolidMesh distorted_unit_cube(int n, double delta) {
  const mesh::SolidMesh box = mesh::make_box_mesh(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {n, n, n});
  std::vector<mesh::SolidPoint> vertices;
  for (int v = 0; v < box.n_vertices(); ++v) {
    const mesh::SolidPoint& x = box.vertex(v);
    const double bump = delta * std::sin(M_PI * x(0)) * std::sin(M_PI * x(1)) * std::sin(M_PI * x(2));
    vertices.push_back(x + bump * Eigen::Vector3d(1.0, -1.0, 1.0));
  }
  std::vector<std::array<int, 8>> cells;
  for (int c = 0; c < box.n_cells(); ++c) cells.push_back(box.cell(c));
  std::vector<std::pair<std::array<int, 4>, std::string>> labels;
  for (const auto& face : box.boundary_faces()) {
    std::array<int, 4> quad{};
    for (int k = 0; k < 4; ++k) quad[k] = box.cell(face.cell)[mesh::kHexFaceVertices[face.local_face][k]];
    labels.emplace_back(quad, face.label);
  }
  return mesh::SolidMesh(std::move(vertices), std::move(cells), "distorted cube", labels);
}

/// The §7 square (x, z) ∈ (−1, 1)² extruded over y ∈ (0, width) with n × n_y × n cells: Γ_C
/// ("contact") at z = −1, Γ_D ("dirichlet") at z = 1 and at x = 1 for z > 0.
/// `shuffle` ≠ 0: vertex numbers and cells' vertex orders shuffled by that seed, so that the trace
/// faces are flipped and swapped in every way (the couplings' signs and face coordinates).
inline mesh::SolidMesh extruded_paper_mesh(int n, int n_y, double width, unsigned shuffle = 0) {
  const mesh::SolidMesh box =
      mesh::make_box_mesh(Eigen::Vector3d(-1.0, 0.0, -1.0), Eigen::Vector3d(1.0, width, 1.0), {n, n_y, n});
  mesh::SolidMesh mesh = shuffle != 0 ? shuffled(box, shuffle) : box;
  mesh.label_boundary_faces([](const mesh::SolidPoint& x) { return x(2) > 1.0 - 1e-9; }, "dirichlet");
  mesh.label_boundary_faces([](const mesh::SolidPoint& x) { return x(0) > 1.0 - 1e-9 && x(2) > 0.0; }, "dirichlet");
  mesh.label_boundary_faces([](const mesh::SolidPoint& x) { return x(2) < -1.0 + 1e-9; }, "contact");
  return mesh;
}

}  // namespace hpcontact::testing
