// The standard and dual multiplier bases, zone by zone of T_{C,H}, as Legendre coefficients.
#include "space/multiplier_family.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>

#include "basis/lobatto.hpp"
#include "core/error.hpp"

namespace hpcontact::space {

std::string to_string(const MultiplierFamily& family) {
  switch (family.kind) {
    case MultiplierFamilyKind::discontinuous:
      return "discontinuous";
    case MultiplierFamilyKind::standard:
      return family.end_modification ? "standard-modified" : "standard";
    case MultiplierFamilyKind::dual:
      return family.end_modification ? "dual-modified" : "dual";
  }
  return {};
}

const std::vector<MultiplierFamily>& all_multiplier_families() {
  static const std::vector<MultiplierFamily> families{{MultiplierFamilyKind::discontinuous, false},
                                                      {MultiplierFamilyKind::standard, false},
                                                      {MultiplierFamilyKind::standard, true},
                                                      {MultiplierFamilyKind::dual, false},
                                                      {MultiplierFamilyKind::dual, true}};
  return families;
}

MultiplierFamily parse_multiplier_family(const std::string& text, const std::string& origin, const std::string& key) {
  for (const auto& family : all_multiplier_families())
    if (to_string(family) == text) return family;
  throw_bad_input(origin, key, text, "must be one of: discontinuous, standard, standard-modified, dual, dual-modified");
}

namespace {

// The global function of each local node of one segment (−1: dropped by the end modification).
struct SegmentNodes {
  int segment = 0;
  std::vector<int> function;
};

// Numbers the nodes of one zone: the Gauss–Lobatto points of each segment, the end points shared
// with the neighbours (and around a closed zone); with the end modification an open zone's two end
// nodes carry no function.
std::vector<SegmentNodes> number_zone(const MultiplierSpace& multipliers, const std::vector<int>& segments, bool closed,
                                      bool modified, FamilyBasis& out) {
  const auto& mesh = multipliers.boundary_mesh();
  auto new_node = [&](int k, double tau) {
    out.node_s.push_back(mesh.segment_begin(k) + 0.5 * (tau + 1.0) * (mesh.segment_end(k) - mesh.segment_begin(k)));
    out.segments.emplace_back();
    return out.n_functions() - 1;
  };
  std::vector<SegmentNodes> zone;
  int zone_first = -1;
  for (std::size_t index = 0; index < segments.size(); ++index) {
    const int k = segments[index], p = multipliers.segment_degree(k);
    const auto tau = basis::gauss_lobatto_points(p);
    SegmentNodes nodes{k, std::vector<int>(static_cast<std::size_t>(p) + 1)};
    const bool first = index == 0, last = index + 1 == segments.size();
    if (first)
      nodes.function.front() = modified && !closed ? -1 : new_node(k, -1.0);
    else
      nodes.function.front() = zone.back().function.back();
    if (first) zone_first = nodes.function.front();
    for (int j = 1; j < p; ++j)
      nodes.function[static_cast<std::size_t>(j)] = new_node(k, tau[static_cast<std::size_t>(j)]);
    if (last && closed)
      nodes.function.back() = zone_first;
    else
      nodes.function.back() = last && modified ? -1 : new_node(k, 1.0);
    for (int f : nodes.function)
      if (f >= 0 && (out.segments[f].empty() || out.segments[f].back() != k)) out.segments[f].push_back(k);
    zone.push_back(std::move(nodes));
  }
  return zone;
}

// Legendre coefficients (rows m = 0..p) of the segment's functions at the kept local nodes
// (columns, in the order of `kept`): on P_{r−1}, r = kept.size(), the Lagrange basis at those
// nodes (standard) or its dual against the degree-p Lagrange φ_j of those nodes (dual).
Eigen::MatrixXd segment_functions(int p, const std::vector<int>& kept, MultiplierFamilyKind kind) {
  const auto tau = basis::gauss_lobatto_points(p);
  const auto r = static_cast<Eigen::Index>(kept.size());
  Eigen::MatrixXd v(p + 1, p + 1);  // V_im = P_m(τ_i)
  for (int i = 0; i <= p; ++i) v.row(i) = basis::legendre_values(p, tau[static_cast<std::size_t>(i)]).transpose();
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(p + 1, r);
  if (kind == MultiplierFamilyKind::standard) {
    out.topRows(r) = v(kept, Eigen::seqN(0, r)).inverse();
    return out;
  }
  // φ_j = Σ_m (V⁻¹)_mj P_m, so ∫ P_m φ_j = 2/(2m+1) (V⁻¹)_mj and ∫ φ_j = 2 (V⁻¹)_0j.
  const Eigen::MatrixXd v_inverse = v.inverse();
  Eigen::MatrixXd mass(r, r);  // M_mj = ∫ P_m φ_j, m < r, j kept
  Eigen::VectorXd integrals(r);
  for (Eigen::Index j = 0; j < r; ++j) {
    const int node = kept[static_cast<std::size_t>(j)];
    for (Eigen::Index m = 0; m < r; ++m) mass(m, j) = 2.0 / (2.0 * m + 1.0) * v_inverse(m, node);
    integrals(j) = 2.0 * v_inverse(0, node);
  }
  // ψ_i = Σ_m A_mi P_m with ∫ ψ_i φ_j = (Aᵀ M)_ij = δ_ij ∫ φ_j: A = M⁻ᵀ D.
  out.topRows(r) = mass.transpose().partialPivLu().solve(Eigen::MatrixXd(integrals.asDiagonal()));
  return out;
}

}  // namespace

FamilyBasis family_basis(const MultiplierSpace& multipliers, const MultiplierFamily& family) {
  HPC_VERIFY(family.kind != MultiplierFamilyKind::discontinuous, "the discontinuous family has no family basis");
  const auto& mesh = multipliers.boundary_mesh();
  for (int k = 0; k < multipliers.n_segments(); ++k)
    if (multipliers.segment_degree(k) < 1)
      throw_bad_input("multiplier family " + to_string(family), "pC", "0",
                      fmt::format("must be >= 1 on every segment (segment {}): the family is continuous or dual to "
                                  "a continuous space",
                                  k));
  FamilyBasis out;
  std::vector<Eigen::Triplet<double>> entries;
  for (int z = 0; z < static_cast<int>(mesh.zones().size()); ++z) {
    std::vector<int> segments;
    for (int k = 0; k < multipliers.n_segments(); ++k)
      if (mesh.zone_of_segment(k) == z) segments.push_back(k);
    if (segments.empty()) continue;
    for (const auto& nodes : number_zone(multipliers, segments, mesh.zones()[z].closed, family.end_modification, out)) {
      std::vector<int> kept;
      for (std::size_t j = 0; j < nodes.function.size(); ++j)
        if (nodes.function[j] >= 0) kept.push_back(static_cast<int>(j));
      if (kept.empty())
        throw InputError(fmt::format(
            "multiplier family {}: zone {} of T_{{C,H}} is one segment of p_C = 1, whose two end nodes the end "
            "modification drops: no multiplier is left (use more segments, p_C >= 2, or the unmodified family)",
            to_string(family), z));
      const int p = multipliers.segment_degree(nodes.segment);
      const Eigen::MatrixXd local = segment_functions(p, kept, family.kind);
      for (Eigen::Index i = 0; i < local.cols(); ++i)
        for (Eigen::Index m = 0; m <= p; ++m)
          if (local(m, i) != 0.0)
            entries.emplace_back(multipliers.first_dof(nodes.segment) + static_cast<int>(m),
                                 nodes.function[static_cast<std::size_t>(kept[static_cast<std::size_t>(i)])],
                                 local(m, i));
    }
  }
  out.legendre.resize(multipliers.n_dofs(), out.n_functions());
  out.legendre.setFromTriplets(entries.begin(), entries.end());
  return out;
}

long long multiplier_function_count(const MultiplierSpace& multipliers, const MultiplierFamily& family) {
  if (family.kind == MultiplierFamilyKind::discontinuous) return multipliers.n_dofs();
  return family_basis(multipliers, family).n_functions();
}

}  // namespace hpcontact::space
