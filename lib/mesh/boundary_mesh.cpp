// BoundaryMesh factories and the common refinement of two 1-D meshes.
#include "mesh/boundary_mesh.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace hpcontact::mesh {

BoundaryMesh::BoundaryMesh(std::vector<double> nodes, const std::string& origin) : nodes_(std::move(nodes)) {
  if (nodes_.size() < 2) throw InputError(origin + ": needs at least one segment");
  if (nodes_.front() != 0.0) throw InputError(origin + ": the first breakpoint must be 0 (the start of Γ_C)");
  for (std::size_t k = 1; k < nodes_.size(); ++k)
    if (!(nodes_[k] > nodes_[k - 1]))
      throw InputError(origin + ": breakpoints must increase strictly (breakpoint " + std::to_string(k) + ")");
  zones_ = {{0.0, nodes_.back(), false}};
}

void BoundaryMesh::set_zones(std::vector<BoundaryZone> zones, const std::string& origin) {
  const double tolerance = 1e-12 * length();
  double at = 0.0;
  for (auto& zone : zones) {
    const auto node = std::min_element(nodes_.begin(), nodes_.end(), [&](double a, double b) {
      return std::abs(a - zone.end) < std::abs(b - zone.end);
    });
    if (std::abs(zone.begin - at) > tolerance || std::abs(*node - zone.end) > tolerance)
      throw InputError(origin + ": the zone [" + std::to_string(zone.begin) + ", " + std::to_string(zone.end) +
                       "] of Γ_C must start where the previous one ends and end at a breakpoint of T_{C,H}");
    zone.begin = at;
    zone.end = at = *node;
  }
  if (zones.empty() || at != length()) throw InputError(origin + ": the zones of Γ_C must cover it to its end");
  zones_ = std::move(zones);
}

int BoundaryMesh::zone_of_segment(int k) const {
  const double middle = 0.5 * (nodes_[k] + nodes_[k + 1]);
  for (std::size_t z = 0; z < zones_.size(); ++z)
    if (middle < zones_[z].end) return static_cast<int>(z);
  return static_cast<int>(zones_.size()) - 1;
}

BoundaryMesh BoundaryMesh::uniform(double length, int m) {
  if (m < 1) throw_bad_input("boundary mesh", "m", std::to_string(m), "must be >= 1");
  std::vector<double> nodes(m + 1);
  for (int k = 0; k <= m; ++k) nodes[k] = length * k / m;
  nodes[m] = length;
  return BoundaryMesh(std::move(nodes));
}

BoundaryMesh BoundaryMesh::graded(double length, int m, double ratio) {
  if (m < 1) throw_bad_input("boundary mesh", "m", std::to_string(m), "must be >= 1");
  if (!(ratio > 0.0 && ratio <= 1.0))
    throw_bad_input("boundary mesh", "grading", std::to_string(ratio), "must be in (0, 1]");
  // Segment sizes symmetric about the middle, shrinking by `ratio` towards each end.
  std::vector<double> sizes(m);
  for (int k = 0; k < m; ++k) sizes[k] = std::pow(ratio, (m - 1) / 2.0 - std::min(k, m - 1 - k));
  double total = 0.0;
  for (double h : sizes) total += h;
  std::vector<double> nodes{0.0};
  for (double h : sizes) nodes.push_back(nodes.back() + h * length / total);
  nodes.back() = length;
  return BoundaryMesh(std::move(nodes));
}

double BoundaryMesh::mesh_size() const {
  double h = 0.0;
  for (int k = 0; k < n_segments(); ++k) h = std::max(h, nodes_[k + 1] - nodes_[k]);
  return h;
}

int BoundaryMesh::segment_at(double s) const {
  const auto it = std::lower_bound(nodes_.begin() + 1, nodes_.end(), s);
  return std::min(static_cast<int>(it - nodes_.begin()) - 1, n_segments() - 1);
}

std::vector<double> common_refinement(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> all(a);
  all.insert(all.end(), b.begin(), b.end());
  std::sort(all.begin(), all.end());
  const double tolerance = 1e-12 * std::max(std::abs(all.back()), 1.0);
  std::vector<double> merged{all.front()};
  for (double s : all)
    if (s - merged.back() > tolerance) merged.push_back(s);
  // Keep the exact end point of the longer mesh.
  merged.back() = all.back();
  return merged;
}

}  // namespace hpcontact::mesh
