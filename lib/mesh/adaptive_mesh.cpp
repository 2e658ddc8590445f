// AdaptiveMesh: red refinement, its 1-irregular balance and the closure by triangles.
#include "mesh/adaptive_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "core/error.hpp"

namespace hpcontact::mesh {
namespace {

std::uint64_t segment_key(int a, int b) {
  const auto [low, high] = std::minmax(a, b);
  return (static_cast<std::uint64_t>(low) << 32) | static_cast<std::uint32_t>(high);
}

}  // namespace

AdaptiveMesh::AdaptiveMesh(const Mesh& coarse, const std::string& origin)
    : coarse_(coarse), origin_(origin), vertices_(coarse.vertices()) {
  if (coarse.is_part()) throw InputError(origin + ": a part of a mesh is not refined adaptively");
  if (coarse.has_curved_cells())
    throw InputError(origin +
                     ": adaptive refinement needs straight cells (its closure triangles cannot follow a "
                     "curve); this mesh has curved cells: use domain.geometry = \"polygonal\"");
  leaves_.reserve(coarse.n_cells());
  for (int c = 0; c < coarse.n_cells(); ++c) {
    Leaf leaf{coarse.cells()[c], {-1, -1, -1, -1}, 0, c};
    // Side k runs from vertex k to vertex k + 1; find the coarse edge with those ends.
    for (int k = 0; k < leaf.size(); ++k)
      for (int local = 0; local < coarse.cell_size(c); ++local) {
        const auto& ends = coarse.edge(coarse.cell_edge(c, local));
        if (segment_key(ends[0], ends[1]) == segment_key(leaf.vertices[k], leaf.vertices[(k + 1) % leaf.size()]))
          leaf.side_origin[k] = coarse.cell_edge(c, local);
      }
    leaves_.push_back(leaf);
  }
}

int AdaptiveMesh::midpoint(int a, int b) const {
  const auto found = midpoints_.find(segment_key(a, b));
  return found == midpoints_.end() ? -1 : found->second;
}

int AdaptiveMesh::make_midpoint(int a, int b) {
  const auto [slot, added] = midpoints_.try_emplace(segment_key(a, b), static_cast<int>(vertices_.size()));
  if (added) vertices_.push_back(0.5 * (vertices_[a] + vertices_[b]));
  return slot->second;
}

int AdaptiveMesh::hanging_side(const Leaf& leaf) const {
  int hanging = -1;
  for (int k = 0; k < leaf.size(); ++k) {
    const int a = leaf.vertices[k], b = leaf.vertices[(k + 1) % leaf.size()];
    const int m = midpoint(a, b);
    if (m < 0) continue;
    if (hanging >= 0 || midpoint(a, m) >= 0 || midpoint(m, b) >= 0) return -2;
    hanging = k;
  }
  return hanging;
}

void AdaptiveMesh::split(const Leaf& leaf, std::vector<Leaf>& out) {
  const int n = leaf.size();
  std::array<int, 4> m{-1, -1, -1, -1};
  for (int k = 0; k < n; ++k) m[k] = make_midpoint(leaf.vertices[k], leaf.vertices[(k + 1) % n]);
  const auto& v = leaf.vertices;
  const auto& o = leaf.side_origin;
  const int level = leaf.level + 1, coarse = leaf.coarse_cell;
  if (n == 3) {
    // Corner children keep two half sides of the parent; the middle one m0 m1 m2 lies inside.
    out.push_back({{v[0], m[0], m[2], -1}, {o[0], -1, o[2], -1}, level, coarse});
    out.push_back({{m[0], v[1], m[1], -1}, {o[0], o[1], -1, -1}, level, coarse});
    out.push_back({{m[2], m[1], v[2], -1}, {-1, o[1], o[2], -1}, level, coarse});
    out.push_back({{m[0], m[1], m[2], -1}, {-1, -1, -1, -1}, level, coarse});
    return;
  }
  // The centre Ψ_T(0, 0) of a straight quadrilateral is the mean of its vertices; the children are
  // the bilinear map restricted to the four sub-squares.
  const int c = static_cast<int>(vertices_.size());
  vertices_.push_back(0.25 * (vertices_[v[0]] + vertices_[v[1]] + vertices_[v[2]] + vertices_[v[3]]));
  out.push_back({{v[0], m[0], c, m[3]}, {o[0], -1, -1, o[3]}, level, coarse});
  out.push_back({{m[0], v[1], m[1], c}, {o[0], o[1], -1, -1}, level, coarse});
  out.push_back({{c, m[1], v[2], m[2]}, {-1, o[1], o[2], -1}, level, coarse});
  out.push_back({{m[3], c, m[2], v[3]}, {-1, -1, o[2], o[3]}, level, coarse});
}

std::vector<int> AdaptiveMesh::refine(const std::vector<int>& marked) {
  std::vector<char> split_now(leaves_.size(), 0);
  for (const int leaf : marked) {
    if (leaf < 0 || leaf >= n_leaves())
      throw InputError(
          fmt::format("{}: leaf {} marked for refinement is not one of the {} leaves", origin_, leaf, n_leaves()));
    split_now[leaf] = 1;
  }
  // parent[k]: the leaf numbered before this call that leaves_[k] lies in.
  std::vector<int> parent(leaves_.size());
  for (int k = 0; k < n_leaves(); ++k) parent[k] = k;
  // Split the marks, then every leaf the balance or the closure rule needs, until none does. A leaf
  // has a hanging side only where a neighbour of its level or finer was split, so no pass splits
  // a leaf of the finest level: the passes end.
  while (std::find(split_now.begin(), split_now.end(), 1) != split_now.end()) {
    std::vector<Leaf> next;
    std::vector<int> next_parent;
    next.reserve(leaves_.size() + 3 * marked.size());
    for (std::size_t k = 0; k < leaves_.size(); ++k) {
      const std::size_t before = next.size();
      if (split_now[k])
        split(leaves_[k], next);
      else
        next.push_back(leaves_[k]);
      next_parent.insert(next_parent.end(), next.size() - before, parent[k]);
    }
    leaves_ = std::move(next), parent = std::move(next_parent);
    split_now.assign(leaves_.size(), 0);
    for (std::size_t k = 0; k < leaves_.size(); ++k) split_now[k] = hanging_side(leaves_[k]) == -2;
  }
  return parent;
}

Mesh AdaptiveMesh::conforming_mesh(std::vector<int>* leaf_of_cell) const {
  std::vector<std::array<int, 4>> cells;
  std::vector<int> leaf_of;
  // The coarse edge under each boundary segment of the closed mesh, by its ends.
  std::map<std::uint64_t, int> origin_of;
  const auto add = [&](int leaf, std::array<int, 4> cell, std::initializer_list<std::array<int, 3>> sides) {
    cells.push_back(cell), leaf_of.push_back(leaf);
    for (const auto& [a, b, origin] : sides)
      if (origin >= 0) origin_of[segment_key(a, b)] = origin;
  };
  for (int l = 0; l < n_leaves(); ++l) {
    const Leaf& leaf = leaves_[l];
    const int n = leaf.size(), k = hanging_side(leaf);
    HPC_VERIFY(k != -2, "a leaf needing refinement after AdaptiveMesh::refine");
    const auto& o = leaf.side_origin;
    if (k < 0) {
      std::initializer_list<std::array<int, 3>> none{};
      add(l, leaf.vertices, none);
      for (int s = 0; s < n; ++s)
        if (o[s] >= 0) origin_of[segment_key(leaf.vertices[s], leaf.vertices[(s + 1) % n])] = o[s];
      continue;
    }
    // q0 q1 … the leaf's vertices from the hanging side's start, m on q0 q1.
    std::array<int, 4> q{}, side{};
    for (int i = 0; i < n; ++i) q[i] = leaf.vertices[(k + i) % n], side[i] = o[(k + i) % n];
    const int m = midpoint(q[0], q[1]);
    if (n == 3) {
      add(l, {q[0], m, q[2], -1}, {{q[0], m, side[0]}, {q[2], q[0], side[2]}});
      add(l, {m, q[1], q[2], -1}, {{m, q[1], side[0]}, {q[1], q[2], side[1]}});
    } else {
      add(l, {q[0], m, q[3], -1}, {{q[0], m, side[0]}, {q[3], q[0], side[3]}});
      add(l, {m, q[1], q[2], -1}, {{m, q[1], side[0]}, {q[1], q[2], side[1]}});
      add(l, {m, q[2], q[3], -1}, {{q[2], q[3], side[2]}});
    }
  }
  Mesh mesh(vertices_, std::move(cells), origin_ + " (adapted)");
  for (const int e : mesh.boundary_edges()) {
    const auto found = origin_of.find(segment_key(mesh.edge(e)[0], mesh.edge(e)[1]));
    HPC_VERIFY(found != origin_of.end(), "a boundary edge of an adapted mesh off every coarse edge");
    mesh.set_edge_label(e, coarse_.edge_label(found->second));
    mesh.set_edge_part(e, coarse_.edge_part(found->second));
  }
  if (leaf_of_cell) *leaf_of_cell = std::move(leaf_of);
  return mesh;
}

}  // namespace hpcontact::mesh
