// The local α predictor (local_alpha.hpp): one small dense eigenproblem per distinct patch.
#include "infsup/local_alpha.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "infsup/infsup_operators.hpp"
#include "space/multiplier_space.hpp"
#include "space/piecewise_space_1d.hpp"

namespace hpcontact::infsup {
namespace {

constexpr double kRelativeTolerance = 1e-10;  // of the length of Γ_C: breakpoints closer than this coincide

// The multiplier functions as Legendre coefficients (T of the family, the identity for the
// discontinuous one), with the range of rows each column touches and whether it meets supp s.
struct MultiplierColumns {
  Eigen::SparseMatrix<double> legendre;
  std::vector<int> first_row, last_row;
  std::vector<bool> meets_support;
};

MultiplierColumns multiplier_columns(const TracePairing& pairing, const space::MultiplierSpace& multipliers) {
  MultiplierColumns out;
  if (pairing.family.kind == space::MultiplierFamilyKind::discontinuous) {
    out.legendre.resize(multipliers.n_dofs(), multipliers.n_dofs());
    out.legendre.setIdentity();
  } else {
    out.legendre = space::family_basis(multipliers, pairing.family).legendre;
  }
  out.legendre.makeCompressed();
  const auto& mesh = *pairing.boundary_mesh;
  std::vector<bool> segment_meets(mesh.n_segments(), true);
  if (pairing.weight) {
    // As the global α's filter: a segment where s vanishes at every sample carries no multiplier.
    const auto& rule = basis::gauss_legendre(8);
    for (int k = 0; k < mesh.n_segments(); ++k) {
      bool meets = false;
      for (const double t : rule.points)
        meets = meets || pairing.weight(mesh.segment_begin(k) +
                                        0.5 * (t + 1) * (mesh.segment_end(k) - mesh.segment_begin(k))) != 0.0;
      segment_meets[k] = meets;
    }
  }
  std::vector<int> segment_of_row(multipliers.n_dofs());
  for (int k = 0; k < mesh.n_segments(); ++k)
    for (int j = 0; j <= multipliers.segment_degree(k); ++j) segment_of_row[multipliers.first_dof(k) + j] = k;
  for (int c = 0; c < out.legendre.cols(); ++c) {
    int first = multipliers.n_dofs(), last = -1;
    bool meets = false;
    for (Eigen::SparseMatrix<double>::InnerIterator it(out.legendre, c); it; ++it) {
      first = std::min(first, static_cast<int>(it.row()));
      last = std::max(last, static_cast<int>(it.row()));
      meets = meets || segment_meets[segment_of_row[it.row()]];
    }
    out.first_row.push_back(first);
    out.last_row.push_back(last);
    out.meets_support.push_back(meets);
  }
  return out;
}

// One patch: the edges [first_edge, end_edge) of T_h (the interval J), the segments inside J
// (their multipliers, as columns R of Legendre coefficients of rows [first_row, end_row)).
struct Patch {
  int first_edge = 0, end_edge = 0;
  int first_segment = 0, end_segment = 0;
  bool zone_end_left = false, zone_end_right = false;  // J ends at the end of an open zone
  bool free_left = false, free_right = false;          // ... where Γ_D does not hold the traces
  int first_row = 0, end_row = 0;
  Eigen::MatrixXd columns;  // R, shape (end_row - first_row, functions)
};

// The discrete interpolation norm's inverse on `space`: with K̃ = K + M/L² (the full H¹ norm at
// the patch's scale) and K̃ X = M X diag(μ), Xᵀ M X = I, the norm is M X diag(√μ) Xᵀ M and its
// inverse X diag(1/√μ) Xᵀ. Shape (n_dofs, n_dofs).
Eigen::MatrixXd inverse_half_norm(const space::PiecewiseSpace1D& space) {
  const double length = space.nodes().back() - space.nodes().front();
  const Eigen::MatrixXd mass = space.mass();
  const Eigen::MatrixXd full = space.stiffness() + mass / (length * length);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen(full, mass);
  if (eigen.info() != Eigen::Success) throw NumericalError("local α: the trace norm's eigenproblem failed");
  const Eigen::VectorXd scale = eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().cwiseInverse();
  return eigen.eigenvectors() * scale.asDiagonal() * eigen.eigenvectors().transpose();
}

// ∫_J w μ_i φ_j ds (w = s if `weighted`, else 1) for the multiplier rows of the patch and the
// functions of `space` (on `pieces`, the common refinement of the edges and segments in J):
// shape (rows, n_dofs).
Eigen::MatrixXd coupling(const TracePairing& pairing, const space::MultiplierSpace& multipliers, const Patch& patch,
                         const std::vector<double>& pieces, const space::PiecewiseSpace1D& space, int quadrature_points,
                         bool weighted) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(patch.end_row - patch.first_row, space.n_dofs());
  const auto& rule = basis::gauss_legendre(quadrature_points);
  const auto& mesh = *pairing.boundary_mesh;
  for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
    const double a = pieces[i], b = pieces[i + 1], mid = 0.5 * (a + b);
    const int segment = mesh.segment_at(mid), piece = space.piece_at(mid);
    if (piece < 0 || segment < patch.first_segment || segment >= patch.end_segment) continue;
    const double p0 = space.nodes()[piece], p1 = space.nodes()[piece + 1];
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double s = a + 0.5 * (rule.points[q] + 1) * (b - a);
      const double w = rule.weights[q] * 0.5 * (b - a) * (weighted ? pairing.weight(s) : 1.0);
      const Eigen::VectorXd mu = multipliers.basis_values(segment, multipliers.local_coordinate(segment, s));
      const auto v = space.values_on(piece, 2 * (s - p0) / (p1 - p0) - 1);
      const int row = multipliers.first_dof(segment) - patch.first_row;
      for (Eigen::Index r = 0; r < mu.size(); ++r)
        for (std::size_t j = 0; j < v.dofs.size(); ++j)
          out(row + r, v.dofs[j]) += w * mu[r] * v.values[static_cast<Eigen::Index>(j)];
    }
  }
  return out;
}

// Sorted union of breakpoint lists, points closer than `tolerance` merged. (Not
// mesh::common_refinement: its absolute 1e-12 would keep the slivers that T_{C,H}'s breakpoints,
// computed in the arc length, leave beside the edges' ends, and a sliver's mass matrix is singular.)
std::vector<double> merged(std::vector<double> a, const std::vector<double>& b, double tolerance) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  std::vector<double> out;
  for (const double x : a)
    if (out.empty() || x - out.back() > tolerance) out.push_back(x);
  return out;
}

// α_J of one patch.
double patch_alpha(const TracePairing& pairing, const space::MultiplierSpace& multipliers, const Patch& patch,
                   double tolerance) {
  std::vector<double> edge_nodes{pairing.edges[patch.first_edge][0]};
  std::vector<int> edge_degrees;
  int top = 0;
  for (int e = patch.first_edge; e < patch.end_edge; ++e) {
    edge_nodes.push_back(pairing.edges[e][1]);
    edge_degrees.push_back(pairing.edge_degrees[e]);
    top = std::max(top, pairing.edge_degrees[e]);
  }
  std::vector<double> segment_nodes;
  for (int k = patch.first_segment; k <= patch.end_segment; ++k) {
    segment_nodes.push_back(pairing.boundary_mesh->nodes()[k]);
    if (k < patch.end_segment) top = std::max(top, multipliers.segment_degree(k));
  }
  // The master's edges wholly inside J, its traces vanishing at their chain's ends.
  std::vector<double> master_nodes;
  std::vector<int> master_degrees;
  const double j0 = edge_nodes.front(), j1 = edge_nodes.back();
  for (std::size_t e = 0; e < pairing.master_edges.size(); ++e) {
    const auto& [m0, m1] = pairing.master_edges[e];
    if (m0 < j0 - tolerance || m1 > j1 + tolerance) continue;
    if (master_nodes.empty() || std::abs(master_nodes.back() - m0) > tolerance) {
      if (!master_nodes.empty()) break;  // a gap: keep the first chain
      master_nodes.push_back(m0);
    }
    master_nodes.push_back(m1);
    master_degrees.push_back(pairing.master_degrees[e]);
    top = std::max(top, pairing.master_degrees[e]);
  }
  // The reference for the dual norm: continuous P_{top+2} on the common refinement of edges and
  // segments in J, rich enough that no multiplier of the patch is invisible to it, and free at a
  // zone's end even where Γ_D holds the traces: ‖μ‖_{-1/2} is the dual of H^{1/2}(Γ_C), as in α.
  const auto pieces = merged(merged(edge_nodes, segment_nodes, tolerance), master_nodes, tolerance);
  const int reference_degree = top + 2;
  const space::PiecewiseSpace1D trace(edge_nodes, edge_degrees, patch.free_left, patch.free_right);
  if (trace.n_dofs() == 0) return 0.0;  // one edge of degree 1 with both ends held
  const space::PiecewiseSpace1D reference(pieces, std::vector<int>(pieces.size() - 1, reference_degree),
                                          patch.zone_end_left, patch.zone_end_right);
  const int points = (reference_degree + top) / 2 + 1 + (pairing.weight ? 4 : 0);
  // The pairing weighs μ by s; its norm does not.
  const Eigen::MatrixXd b_trace =
      patch.columns.transpose() * coupling(pairing, multipliers, patch, pieces, trace, points, bool(pairing.weight));
  const Eigen::MatrixXd b_reference =
      patch.columns.transpose() * coupling(pairing, multipliers, patch, pieces, reference, points, false);
  Eigen::MatrixXd s = b_trace * inverse_half_norm(trace) * b_trace.transpose();
  if (master_nodes.size() >= 2) {
    const space::PiecewiseSpace1D master(master_nodes, master_degrees, false, false);
    if (master.n_dofs() > 0) {
      const Eigen::MatrixXd b_master = patch.columns.transpose() * coupling(pairing, multipliers, patch, pieces, master,
                                                                            points, bool(pairing.weight));
      s += b_master * inverse_half_norm(master) * b_master.transpose();
    }
  }
  const Eigen::MatrixXd g = b_reference * inverse_half_norm(reference) * b_reference.transpose();
  // (Eigen's generalized solver does not check that g is positive definite: checked here)
  if (!g.allFinite() || Eigen::LLT<Eigen::MatrixXd>(g).info() != Eigen::Success)
    throw NumericalError("local α: the H^{-1/2} Gram of a patch is not positive definite");
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen(s, g, Eigen::EigenvaluesOnly);
  if (eigen.info() != Eigen::Success || !eigen.eigenvalues().allFinite())
    throw NumericalError("local α: a patch's eigenproblem failed");
  return std::sqrt(std::max(0.0, eigen.eigenvalues().minCoeff()));
}

// What makes two patches the same eigenproblem: the breakpoints relative to J, the degrees,
// the free ends and R (no weight: with one the data differ from patch to patch).
std::string patch_key(const TracePairing& pairing, const space::MultiplierSpace& multipliers, const Patch& patch) {
  const double a = pairing.edges[patch.first_edge][0], length = pairing.edges[patch.end_edge - 1][1] - a;
  std::string key = std::to_string(patch.free_left) + std::to_string(patch.free_right) +
                    std::to_string(patch.zone_end_left) + std::to_string(patch.zone_end_right) + "|";
  const auto add = [&](double x) { key += std::to_string(std::lround((x - a) / length * 1e9)) + ","; };
  for (int e = patch.first_edge; e < patch.end_edge; ++e) {
    add(pairing.edges[e][1]);
    key += std::to_string(pairing.edge_degrees[e]) + ";";
  }
  key += "|";
  add(pairing.boundary_mesh->segment_begin(patch.first_segment));
  for (int k = patch.first_segment; k < patch.end_segment; ++k) {
    add(pairing.boundary_mesh->segment_end(k));
    key += std::to_string(multipliers.segment_degree(k)) + ";";
  }
  key += "|";
  for (std::size_t e = 0; e < pairing.master_edges.size(); ++e)
    if (pairing.master_edges[e][1] > a && pairing.master_edges[e][0] < a + length) {
      add(pairing.master_edges[e][0]);
      add(pairing.master_edges[e][1]);
      key += std::to_string(pairing.master_degrees[e]) + ";";
    }
  key += "|";
  for (Eigen::Index i = 0; i < patch.columns.size(); ++i)
    key += std::to_string(std::lround(patch.columns.data()[i] * 1e9)) + ",";
  return key;
}

// The patch's multiplier functions per length over its trace unknowns per length (both bodies'
// for a pair). At 1 or more the traces cannot control the multipliers uniformly in h even where
// α_J > 0: the modes that make α decay like h (p_C = p − 1 on T_h's edges, p_C = p at h/H = 2/3)
// balance the counts exactly.
double density_ratio(const TracePairing& pairing, const Patch& patch) {
  const auto& mesh = *pairing.boundary_mesh;
  const double j0 = pairing.edges[patch.first_edge][0], j1 = pairing.edges[patch.end_edge - 1][1];
  double traces = 0.0;
  for (int e = patch.first_edge; e < patch.end_edge; ++e) traces += pairing.edge_degrees[e];
  for (std::size_t e = 0; e < pairing.master_edges.size(); ++e)
    if (pairing.master_edges[e][1] > j0 && pairing.master_edges[e][0] < j1)
      traces += pairing.master_degrees[e] *
                (std::min(j1, pairing.master_edges[e][1]) - std::max(j0, pairing.master_edges[e][0])) /
                (pairing.master_edges[e][1] - pairing.master_edges[e][0]);
  const double covered = mesh.segment_begin(patch.end_segment) - mesh.segment_begin(patch.first_segment);
  return (static_cast<double>(patch.columns.cols()) / covered) / (traces / (j1 - j0));
}

// min over the edges of J of min(1, 2 √(h/d)): the cells taller than their edge (header).
double depth_factor(const TracePairing& pairing, const Patch& patch) {
  double factor = 1.0;
  if (pairing.edge_depths.empty()) return factor;
  for (int e = patch.first_edge; e < patch.end_edge; ++e) {
    const double h = pairing.edges[e][1] - pairing.edges[e][0], d = pairing.edge_depths[e];
    if (d > 0) factor = std::min(factor, 2.0 * std::sqrt(h / d));
  }
  return factor;
}

// Γ_C's edges and T_{C,H} as the patches need them: the edges under an arc, the zones' segments.
class PatchMaker {
 public:
  PatchMaker(const TracePairing& pairing, const space::MultiplierSpace& multipliers, const MultiplierColumns& columns)
      : pairing_(pairing),
        mesh_(*pairing.boundary_mesh),
        multipliers_(multipliers),
        columns_(columns),
        tolerance_(kRelativeTolerance * mesh_.length()),
        zone_first_(mesh_.zones().size(), mesh_.n_segments()),
        zone_last_(mesh_.zones().size(), -1) {
    for (int k = 0; k < mesh_.n_segments(); ++k) {
      const int z = mesh_.zone_of_segment(k);
      zone_first_[z] = std::min(zone_first_[z], k);
      zone_last_[z] = std::max(zone_last_[z], k);
    }
  }
  double tolerance() const { return tolerance_; }

  /// The patch of segment k: the edges under it and its zone neighbours, the segments wholly
  /// inside them and their multiplier functions (R); none without a function.
  std::optional<Patch> patch(int k) const {
    const int z = mesh_.zone_of_segment(k);
    const auto& zone = mesh_.zones()[z];
    const int lo = std::max(k - 1, zone_first_[z]), hi = std::min(k + 1, zone_last_[z]);
    Patch patch;
    patch.first_edge = edge_ending_after(mesh_.segment_begin(lo));
    patch.end_edge = edge_beginning_at(mesh_.segment_end(hi));
    HPC_VERIFY(patch.first_edge < patch.end_edge, "T_{C,H} spans the edges of Γ_C");
    const auto& edges = pairing_.edges;
    const double j0 = edges[patch.first_edge][0], j1 = edges[patch.end_edge - 1][1];
    // The segments wholly inside J (J covers lo..hi at least).
    patch.first_segment = mesh_.segment_at(j0 + tolerance_);
    if (mesh_.segment_begin(patch.first_segment) < j0 - tolerance_) ++patch.first_segment;
    patch.end_segment = mesh_.segment_at(j1 - tolerance_) + 1;
    if (mesh_.segment_end(patch.end_segment - 1) > j1 + tolerance_) --patch.end_segment;
    HPC_VERIFY(patch.first_segment < patch.end_segment, "J covers its own segments");
    const auto held = [&](int end) { return !pairing_.held_zone_ends.empty() && pairing_.held_zone_ends[z][end]; };
    patch.zone_end_left = !zone.closed && std::abs(j0 - zone.begin) < tolerance_;
    patch.zone_end_right = !zone.closed && std::abs(j1 - zone.end) < tolerance_;
    patch.free_left = patch.zone_end_left && !held(0);
    patch.free_right = patch.zone_end_right && !held(1);
    patch.first_row = multipliers_.first_dof(patch.first_segment);
    patch.end_row =
        multipliers_.first_dof(patch.end_segment - 1) + multipliers_.segment_degree(patch.end_segment - 1) + 1;
    std::vector<int> inside;
    for (int c = 0; c < columns_.legendre.cols(); ++c)
      if (columns_.meets_support[c] && columns_.first_row[c] >= patch.first_row && columns_.last_row[c] < patch.end_row)
        inside.push_back(c);
    if (inside.empty()) return std::nullopt;
    patch.columns.setZero(patch.end_row - patch.first_row, static_cast<Eigen::Index>(inside.size()));
    for (std::size_t j = 0; j < inside.size(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(columns_.legendre, inside[j]); it; ++it)
        patch.columns(it.row() - patch.first_row, static_cast<Eigen::Index>(j)) = it.value();
    return patch;
  }

  /// Π on segment k: its longest edge and the smallest trace degree there.
  double pi(int k) const {
    double h = 0.0;
    int p = std::numeric_limits<int>::max();
    for (int e = edge_ending_after(mesh_.segment_begin(k)); e < edge_beginning_at(mesh_.segment_end(k)); ++e) {
      h = std::max(h, pairing_.edges[e][1] - pairing_.edges[e][0]);
      p = std::min(p, pairing_.edge_degrees[e]);
    }
    HPC_VERIFY(h > 0, "a segment over edges of Γ_C");
    return stability_indicator(h, mesh_.segment_end(k) - mesh_.segment_begin(k), p, multipliers_.segment_degree(k));
  }

 private:
  // The first edge ending after s, and the first edge beginning at or after s.
  int edge_ending_after(double s) const {
    const auto& edges = pairing_.edges;
    return static_cast<int>(
        std::partition_point(edges.begin(), edges.end(), [&](const auto& e) { return e[1] <= s + tolerance_; }) -
        edges.begin());
  }
  int edge_beginning_at(double s) const {
    const auto& edges = pairing_.edges;
    return static_cast<int>(
        std::partition_point(edges.begin(), edges.end(), [&](const auto& e) { return e[0] < s - tolerance_; }) -
        edges.begin());
  }

  const TracePairing& pairing_;
  const mesh::BoundaryMesh& mesh_;
  const space::MultiplierSpace& multipliers_;
  const MultiplierColumns& columns_;
  double tolerance_;
  std::vector<int> zone_first_, zone_last_;
};

}  // namespace

PredictedAlpha predict_alpha(const TracePairing& pairing) {
  const auto& mesh = *pairing.boundary_mesh;
  HPC_VERIFY(!pairing.edges.empty() && pairing.edges.size() == pairing.edge_degrees.size(), "trace edges with degrees");
  HPC_VERIFY(static_cast<int>(pairing.segment_degrees.size()) == mesh.n_segments(), "one p_C per segment");
  HPC_VERIFY(pairing.held_zone_ends.empty() || pairing.held_zone_ends.size() == mesh.zones().size(),
             "held ends for every zone");
  const space::MultiplierSpace multipliers(mesh, pairing.segment_degrees);
  const auto columns = multiplier_columns(pairing, multipliers);
  const PatchMaker maker(pairing, multipliers, columns);
  PredictedAlpha out;
  out.alpha = std::numeric_limits<double>::infinity();
  std::map<std::string, double> solved;  // α_J by patch_key; a weight differs from patch to patch
  for (int k = 0; k < mesh.n_segments(); ++k) {
    out.pi = std::max(out.pi, maker.pi(k));
    const auto patch = maker.patch(k);
    if (!patch) continue;
    ++out.patches;
    double alpha = 0.0;
    const auto key = pairing.weight ? std::string() : patch_key(pairing, multipliers, *patch);
    const auto found = solved.find(key);
    if (!key.empty() && found != solved.end()) {
      alpha = found->second;
    } else {
      alpha = patch_alpha(pairing, multipliers, *patch, maker.tolerance());
      if (!key.empty()) solved[key] = alpha;
      ++out.distinct_patches;
    }
    alpha *= depth_factor(pairing, *patch);
    if (density_ratio(pairing, *patch) >= 1.0 - 1e-9) alpha = 0.0;
    if (alpha < out.alpha) out.alpha = alpha, out.weakest_segment = k;
  }
  if (out.patches == 0) out.alpha = 0.0;
  return out;
}

}  // namespace hpcontact::infsup
