// interpolation_norm_gram_on_reference and extension_norm_gram.
#include "norms/h_minus_half_gram.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <vector>

#include "assembly/coupling.hpp"
#include "assembly/poisson_assembly.hpp"
#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "mesh/contact_point_separation.hpp"
#include "mesh/point_grading.hpp"
#include "mesh/refine.hpp"

namespace hpcontact::norms {

Eigen::MatrixXd interpolation_norm_gram_on_reference(const mesh::ContactBoundary& contact,
                                                     const space::MultiplierSpace& multipliers,
                                                     const InterpolationReference& reference) {
  if (reference.subdivisions < 1)
    throw_bad_input("interpolation norm", "subdivisions", std::to_string(reference.subdivisions), "must be >= 1");
  const int q = reference.degree > 0 ? reference.degree : multipliers.max_degree() + 6;
  // W's mesh contains the breakpoints of T_{C,H}, so every W interval lies in one segment.
  std::vector<double> nodes;
  for (const auto& interval : assembly::common_intervals(contact, multipliers.boundary_mesh()))
    for (int k = 0; k < reference.subdivisions; ++k)
      nodes.push_back(interval.s_begin + (interval.s_end - interval.s_begin) * k / reference.subdivisions);
  nodes.push_back(contact.length());
  const int n_intervals = static_cast<int>(nodes.size()) - 1;
  // Dofs: the vertices of each zone (W is continuous within a zone, not across zones: interval k
  // of zone z has vertices k + z and k + z + 1), then q - 1 bubbles per interval.
  const auto& boundary = multipliers.boundary_mesh();
  const int n_zones = static_cast<int>(boundary.zones().size());
  for (const auto& zone : boundary.zones())
    if (zone.closed) throw InputError("the interpolation norm on a reference space is built for open zones of Γ_C");
  const int n_vertices = n_intervals + n_zones;
  const int n_w = n_vertices + n_intervals * (q - 1);
  std::vector<Eigen::Triplet<double>> a_entries, m_entries, c_entries;
  const int pc_max = multipliers.max_degree();
  const auto& rule = basis::gauss_legendre(basis::gauss_points_for_degree(2 * q + pc_max));
  const auto table = basis::tabulate_lobatto(q, rule.points);
  for (int k = 0; k < n_intervals; ++k) {
    const int segment = boundary.segment_at(0.5 * (nodes[k] + nodes[k + 1]));
    const int zone = boundary.zone_of_segment(segment);
    std::vector<int> dofs{k + zone, k + zone + 1};
    for (int j = 2; j <= q; ++j) dofs.push_back(n_vertices + k * (q - 1) + (j - 2));
    const double half = 0.5 * (nodes[k + 1] - nodes[k]);
    const int first = multipliers.first_dof(segment), pc = multipliers.segment_degree(segment);
    Eigen::MatrixXd a_local = Eigen::MatrixXd::Zero(q + 1, q + 1), m_local = a_local;
    Eigen::MatrixXd c_local = Eigen::MatrixXd::Zero(q + 1, pc + 1);
    for (std::size_t g = 0; g < rule.points.size(); ++g) {
      const double w = rule.weights[g] * half;
      const double s = nodes[k] + half * (rule.points[g] + 1.0);
      const Eigen::VectorXd mu = multipliers.basis_values(segment, multipliers.local_coordinate(segment, s));
      for (int a = 0; a <= q; ++a) {
        const double value_a = table.values(g, a), slope_a = table.derivatives(g, a) / half;
        for (int b = 0; b <= q; ++b) {
          const double product = w * value_a * table.values(g, b);
          m_local(a, b) += product;
          a_local(a, b) += product + w * slope_a * table.derivatives(g, b) / half;
        }
        c_local.row(a) += w * value_a * mu.transpose();
      }
    }
    for (int a = 0; a <= q; ++a) {
      for (int b = 0; b <= q; ++b) {
        a_entries.emplace_back(dofs[a], dofs[b], a_local(a, b));
        m_entries.emplace_back(dofs[a], dofs[b], m_local(a, b));
      }
      for (int j = 0; j <= pc; ++j) c_entries.emplace_back(dofs[a], first + j, c_local(a, j));
    }
  }
  Eigen::SparseMatrix<double> stiffness_plus_mass(n_w, n_w), mass(n_w, n_w), coupling(n_w, multipliers.n_dofs());
  stiffness_plus_mass.setFromTriplets(a_entries.begin(), a_entries.end());
  mass.setFromTriplets(m_entries.begin(), m_entries.end());
  coupling.setFromTriplets(c_entries.begin(), c_entries.end());
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen{Eigen::MatrixXd(stiffness_plus_mass),
                                                                        Eigen::MatrixXd(mass)};
  if (eigen.info() != Eigen::Success)
    throw NumericalError("interpolation norm: the reference eigenproblem K_W Φ = M_W Φ Λ failed");
  const Eigen::MatrixXd scaled = eigen.eigenvectors().transpose() * coupling;  // Φᵀ C, shape (n_w, n_mult)
  const Eigen::VectorXd inverse_sqrt = eigen.eigenvalues().cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd gram = scaled.transpose() * inverse_sqrt.asDiagonal() * scaled;
  return 0.5 * (gram + gram.transpose());
}

Eigen::MatrixXd restrict_gram(const Eigen::MatrixXd& envelope_gram, const space::MultiplierSpace& envelope,
                              const space::MultiplierSpace& sub) {
  HPC_VERIFY(envelope_gram.rows() == envelope.n_dofs() && sub.n_segments() == envelope.n_segments(),
             "restrict_gram: the spaces do not share their segments");
  std::vector<int> modes;
  for (int k = 0; k < sub.n_segments(); ++k) {
    HPC_VERIFY(std::abs(sub.boundary_mesh().segment_end(k) - envelope.boundary_mesh().segment_end(k)) <=
                       1e-12 * envelope.boundary_mesh().length() &&
                   sub.segment_degree(k) <= envelope.segment_degree(k),
               "restrict_gram: the spaces do not share their segments, or the envelope's degree is lower");
    for (int j = 0; j <= sub.segment_degree(k); ++j) modes.push_back(envelope.first_dof(k) + j);
  }
  return envelope_gram(modes, modes);
}

ExtensionReference extension_reference_at(int level) {
  // No refinement unless the grading needs it (breakpoints inside edges that cannot be cut): the
  // references on T_h itself cost a quarter, at the same accuracy (α within 2e-5).
  // Level 0 with 3 layers and p_T + 3 keeps the change to level 1 within 1e-4 α where level 1
  // is enough (n = 128, p = 4, p_C = 3: 2.8e-5 α), so that two references do.
  return {
      .refinements = 0, .layers = 3 + 2 * level, .grading = 0.2, .extra_degree = 3 + level, .far_extra_degree = level};
}

namespace {

// The vertices of `mesh` at the arc lengths `points` on Γ_C, or nothing if one is not a vertex or
// two share a cell (grading needs disjoint stars).
std::optional<std::vector<int>> grading_vertices(const mesh::Mesh& mesh, const std::vector<double>& points) {
  const mesh::ContactBoundary contact(mesh);
  const auto trace = contact.breakpoints();
  const double tolerance = 1e-9 * contact.length();
  std::map<int, int> wanted;  // vertex -> cells of its star seen so far
  std::vector<int> vertices;
  for (double s : points) {
    const auto at = std::lower_bound(trace.begin(), trace.end(), s - tolerance);
    if (at == trace.end() || std::abs(*at - s) > tolerance) return std::nullopt;
    // The trace vertex is an end of the trace edge beside it.
    const auto& edge = contact.edges()[std::min<std::size_t>(at - trace.begin(), contact.edges().size() - 1)];
    const auto [a, b] = mesh.edge(edge.edge);
    const mesh::Point x = contact.point_at(*at);
    const int vertex = (mesh.vertex(a) - x).norm() < (mesh.vertex(b) - x).norm() ? a : b;
    // A closed zone's end is its start: the same vertex.
    if (wanted.contains(vertex)) continue;
    vertices.push_back(vertex);
    wanted[vertex] = 0;
  }
  std::vector<int> star_of(mesh.n_cells(), -1);
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int v : mesh.cell(c))
      if (wanted.contains(v)) {
        if (star_of[c] >= 0 && star_of[c] != v) return std::nullopt;  // two stars share the cell
        star_of[c] = v;
      }
  return vertices;
}

// Whether each cell has a vertex on Γ_C.
std::vector<char> cells_at_contact(const mesh::Mesh& mesh) {
  std::vector<char> on_contact(mesh.n_vertices(), 0), at(mesh.n_cells(), 0);
  for (int e : mesh.boundary_edges())
    if (mesh.edge_part(e) == mesh::BoundaryPart::contact)
      for (int v : mesh.edge(e)) on_contact[v] = 1;
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int v : mesh.cell(c))
      if (on_contact[v]) at[c] = 1;
  return at;
}

// The vertices of ∂Ω where the boundary part changes or the boundary turns by more than 30°
// (corners), where u^μ is singular.
std::vector<int> singular_boundary_vertices(const mesh::Mesh& mesh) {
  std::map<int, std::vector<int>> edges_at;
  for (int e : mesh.boundary_edges())
    for (int v : mesh.edge(e)) edges_at[v].push_back(e);
  std::vector<int> singular;
  for (const auto& [vertex, edges] : edges_at) {
    if (edges.size() != 2) continue;  // a vertex where the boundary touches itself: left alone
    const int v = vertex;             // (a structured binding is not captured by clang 14's lambdas)
    const auto away = [&](int e) {
      const auto& ends = mesh.edge(e);
      return mesh.vertex(ends[0] == v ? ends[1] : ends[0]) - mesh.vertex(v);
    };
    // The boundary turns by more than 30° (a polygonal curve's small turns are not corners).
    const mesh::Point a = away(edges[0]), b = away(edges[1]);
    const bool turns = a.dot(b) > -std::cos(std::numbers::pi / 6) * a.norm() * b.norm();
    if (turns || mesh.edge_part(edges[0]) != mesh.edge_part(edges[1])) singular.push_back(v);
  }
  return singular;
}

}  // namespace

ExtensionReferenceFactor::ExtensionReferenceFactor(const mesh::Mesh* mesh, const std::vector<int>& cell_degrees,
                                                   const ExtensionReference& reference,
                                                   const std::vector<double>& grading_points,
                                                   linalg::Distribution distribution, int n_multipliers) {
  if (reference.refinements < 0 || reference.extra_degree < 0 || reference.layers < 0)
    throw InputError("extension norm: refinements, layers and extra_degree must be >= 0");
  // S_ref's mesh is built where T_h is: distributed, on the first rank alone, which sends each
  // rank its part of it (PrimalOperators); a failure there is raised on every rank.
  const bool distributed = distribution.distributed();
  const bool builds = !distributed || rank_and_size(distribution.ranks).first == 0;
  std::vector<int> degrees;
  const auto build = [&] {
    if (!builds) return;
    HPC_VERIFY(mesh, "the extension norm's references refine the whole mesh, which was not given");
    fine_ = std::make_unique<mesh::Mesh>(*mesh);
    degrees = cell_degrees;
    refine_reference(reference, grading_points, degrees);
  };
  if (distributed) {
    run_on_all_ranks_agreeing(build, distribution.ranks);
    int graded = graded_ ? 1 : 0;
    HPC_VERIFY(MPI_Bcast(&graded, 1, MPI_INT, 0, distribution.ranks) == MPI_SUCCESS,
               "broadcast of whether the reference is graded");
    graded_ = graded == 1;
  } else {
    build();
  }
  operators_ = std::make_unique<operators::PrimalOperators>(fine_.get(), std::move(degrees), nullptr, distribution);
  // Distributed, the operators hold the rank's part of S_ref: the whole refined mesh goes before
  // the factorization, the run's peak.
  if (distribution.distributed()) fine_.reset();
  // Distributed, the solvers decide for themselves where the trace goes (trailing_joins_interface).
  operators_->gram_factor(distribution.distributed()
                              ? operators::PrimalOperators::TraceOrdering::last
                              : trace_ordering_for(operators_->space().n_dofs(),
                                                   static_cast<long long>(operators_->trace_dofs().size()),
                                                   n_multipliers));
}

void ExtensionReferenceFactor::refine_reference(const ExtensionReference& reference,
                                                const std::vector<double>& grading_points, std::vector<int>& degrees) {
  // Which cells get the high degree (at Γ_C or in a singular point's star), carried to the children.
  std::vector<char> near = cells_at_contact(*fine_);
  const auto adopt_children = [&](const std::vector<int>& parents) {
    std::vector<int> child_degrees(parents.size());
    std::vector<char> child_near(parents.size());
    for (std::size_t c = 0; c < parents.size(); ++c) {
      child_degrees[c] = degrees[parents[c]];
      child_near[c] = near[parents[c]];
    }
    degrees = std::move(child_degrees);
    near = std::move(child_near);
  };
  const auto refine = [&] {
    *fine_ = mesh::refine_uniformly(*fine_);
    std::vector<int> parents(4 * degrees.size());
    for (std::size_t c = 0; c < parents.size(); ++c) parents[c] = static_cast<int>(c / 4);  // children 4c..4c+3
    adopt_children(parents);
  };
  for (int level = 0; level < reference.refinements; ++level) refine();
  if (fine_->has_curved_cells()) {
    // Grading would move vertices off the curves: refine uniformly instead (one level per two
    // layers, at most two), and report the reference as not geometric.
    for (int level = 0; level < std::min(reference.layers / 2, 2); ++level) refine();
  } else if (reference.layers > 0 && !grading_points.empty()) {
    auto centres = grading_vertices(*fine_, grading_points);
    // Breakpoints of T_{C,H} one edge apart or inside edges of T_h: cut the cells on Γ_C, or
    // where that cannot be done locally, refine the whole mesh (twice at most; beyond that the
    // grading is left out and the error estimate shows it).
    if (!centres)
      if (auto cut = mesh::separate_contact_points(*fine_, grading_points)) {
        centres = grading_vertices(cut->mesh, grading_points);
        if (centres) {
          *fine_ = std::move(cut->mesh);
          adopt_children(cut->parents);
        }
      }
    for (int extra = 0; !centres && extra < 2; ++extra) {
      refine();
      centres = grading_vertices(*fine_, grading_points);
    }
    graded_ = centres.has_value();
    if (centres) add_singular_points(*centres, near);
    if (centres) {
      std::vector<int> parents;
      *fine_ = mesh::grade_towards_vertices(*fine_, *centres, reference.grading, reference.layers,
                                            "extension reference", &parents);
      adopt_children(parents);
    }
  }
  if (fine_->has_curved_cells()) graded_ = false;
  for (std::size_t c = 0; c < degrees.size(); ++c)
    degrees[c] =
        near[c] ? degrees[c] + reference.extra_degree : std::max(1, degrees[c] - 3) + reference.far_extra_degree;
}

void ExtensionReferenceFactor::add_singular_points(std::vector<int>& centres, std::vector<char>& near) {
  std::vector<int> star_of(fine_->n_cells(), -1);
  const auto in_star = [&](int c, int v) {
    const auto cell = fine_->cell(c);
    return std::find(cell.begin(), cell.end(), v) != cell.end();
  };
  for (int c = 0; c < fine_->n_cells(); ++c)
    for (int v : centres)
      if (in_star(c, v)) star_of[c] = v;
  for (int v : singular_boundary_vertices(*fine_)) {
    if (std::find(centres.begin(), centres.end(), v) != centres.end()) continue;  // a breakpoint already
    bool disjoint = true;
    for (int c = 0; c < fine_->n_cells(); ++c) disjoint = disjoint && !(in_star(c, v) && star_of[c] >= 0);
    // A star that would share a cell with another (a mesh too coarse there) is not graded: then
    // the reference does not converge geometrically, and says so.
    if (!disjoint) {
      graded_ = false;
      continue;
    }
    for (int c = 0; c < fine_->n_cells(); ++c)
      if (in_star(c, v)) star_of[c] = v, near[c] = 1;
    centres.push_back(v);
  }
}

operators::PrimalOperators::TraceOrdering trace_ordering_for(long long n_unknowns, long long n_trace,
                                                             long long n_multipliers) {
  const double trace = static_cast<double>(n_trace);
  return trace * trace * trace <= 400.0 * static_cast<double>(n_multipliers) * static_cast<double>(n_unknowns)
             ? operators::PrimalOperators::TraceOrdering::last
             : operators::PrimalOperators::TraceOrdering::free;
}

Eigen::MatrixXd extension_norm_gram(const ExtensionReferenceFactor& reference,
                                    const space::MultiplierSpace& multipliers) {
  const auto& reference_operators = reference.operators();
  return reference_operators.gram_factor().schur_complement(
      assembly::assemble_coupling(reference_operators.space(), reference_operators.contact(), multipliers));
}

Eigen::MatrixXd extension_norm_gram(const mesh::Mesh* mesh, const std::vector<int>& cell_degrees,
                                    const space::MultiplierSpace& multipliers, const ExtensionReference& reference,
                                    bool* graded, linalg::Distribution distribution) {
  const ExtensionReferenceFactor factor(mesh, cell_degrees, reference, multipliers.boundary_mesh().nodes(),
                                        distribution, multipliers.n_dofs());
  if (graded) *graded = factor.graded();
  return extension_norm_gram(factor, multipliers);
}

}  // namespace hpcontact::norms
