// assemble_infsup_operators.
#include "infsup/infsup_operators.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "assembly/mortar_coupling.hpp"
#include "assembly/poisson_assembly.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "linalg/sparse_stack.hpp"
#include "mesh/contact_boundary.hpp"
#include "operators/primal_operators.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::infsup {

GramNorm parse_gram_norm(const std::string& text, const std::string& origin) {
  if (text == "interp" || text == "interpolation") return GramNorm::interpolation;
  if (text == "extension") return GramNorm::extension;
  throw_bad_input(origin, "norm", text, "must be one of: interp, extension");
}

PairingProblem parse_pairing_problem(const std::string& text, const std::string& origin) {
  if (text == "signorini") return PairingProblem::signorini;
  if (text == "friction") return PairingProblem::friction;
  throw_bad_input(origin, "problem", text, "must be one of: signorini, friction");
}

std::string to_string(GramNorm norm) { return norm == GramNorm::interpolation ? "interp" : "extension"; }
std::string to_string(PairingProblem problem) {
  return problem == PairingProblem::signorini ? "signorini" : "friction";
}

double stability_indicator(double h, double H, int min_p, int max_pc) {
  const double pc = std::max(1, max_pc);
  return h / H * pc * pc / min_p;
}

namespace {

// Segments on which s vanishes at every sample point carry no multiplier in (22).
std::vector<bool> segments_meeting_support(const mesh::ContactBoundary& contact,
                                           const space::MultiplierSpace& multipliers,
                                           const assembly::BoundaryFunction& s) {
  std::vector<bool> meets(static_cast<std::size_t>(multipliers.n_segments()));
  const auto& rule = basis::gauss_legendre(12);
  for (int k = 0; k < multipliers.n_segments(); ++k) {
    const double a = multipliers.boundary_mesh().segment_begin(k);
    const double b = multipliers.boundary_mesh().segment_end(k);
    meets[static_cast<std::size_t>(k)] = std::any_of(rule.points.begin(), rule.points.end(), [&](double t) {
      return s(contact.point_at(a + 0.5 * (b - a) * (t + 1.0))) != 0.0;
    });
  }
  return meets;
}

// R: the family's functions (Legendre modes for the discontinuous family) in `copies` copies,
// those whose segments meet `active` (every segment when empty).
Eigen::SparseMatrix<double> pencil_basis(const space::MultiplierSpace& multipliers,
                                         const space::MultiplierFamily& family, int copies,
                                         const std::vector<bool>& active = {}) {
  const int n = multipliers.n_dofs();
  Eigen::SparseMatrix<double> functions(n, n);
  if (family.kind == space::MultiplierFamilyKind::discontinuous)
    functions.setIdentity();
  else
    functions = space::family_basis(multipliers, family).legendre;
  std::vector<int> segment_of_dof(static_cast<std::size_t>(n));
  for (int k = 0; k < multipliers.n_segments(); ++k)
    for (int m = 0; m <= multipliers.segment_degree(k); ++m)
      segment_of_dof[static_cast<std::size_t>(multipliers.first_dof(k) + m)] = k;
  std::vector<Eigen::Triplet<double>> entries;
  int kept = 0;
  for (int copy = 0; copy < copies; ++copy)
    for (int c = 0; c < functions.outerSize(); ++c) {
      bool keep = active.empty();
      for (Eigen::SparseMatrix<double>::InnerIterator it(functions, c); it && !keep; ++it)
        keep = active[static_cast<std::size_t>(segment_of_dof[static_cast<std::size_t>(it.row())])];
      if (!keep) continue;
      for (Eigen::SparseMatrix<double>::InnerIterator it(functions, c); it; ++it)
        entries.emplace_back(copy * n + static_cast<int>(it.row()), kept, it.value());
      ++kept;
    }
  Eigen::SparseMatrix<double> out(copies * n, kept);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

}  // namespace

Eigen::MatrixXd restrict(const Eigen::MatrixXd& matrix, const Eigen::SparseMatrix<double>& basis) {
  bool identity = basis.rows() == basis.cols() && basis.nonZeros() == basis.rows();
  for (int c = 0; identity && c < basis.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(basis, c); it; ++it)
      identity = identity && it.row() == c && it.value() == 1.0;
  if (identity) return matrix;
  return Eigen::MatrixXd(basis.transpose() * (matrix * basis));
}

Eigen::MatrixXd block_copies(const Eigen::MatrixXd& g, int copies) {
  if (copies == 1) return g;
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(copies * g.rows(), copies * g.cols());
  for (int k = 0; k < copies; ++k) out.block(k * g.rows(), k * g.cols(), g.rows(), g.cols()) = g;
  return out;
}

namespace {

// The master's share of S_G of a contact pair: B_m A_{G,m}⁻¹ B_mᵀ with B_m the mortar coupling of
// its traces through Φ along the slave's normal (and tangent), the sign of b irrelevant here.
void add_master_pairing(const InfSupSetup& setup, const space::MultiplierSpace& multipliers, InfSupOperators& out) {
  HPC_VERIFY(setup.projection, "a contact pair's inf-sup setup without the projection onto the master");
  const auto& master = *setup.master;
  const auto& slave = setup.elastic->contact();
  Stopwatch assembly_clock;
  auto coupling = [&](assembly::TraceDirection direction) {
    return assembly::assemble_directional_mortar_coupling(master.vector_space(), *setup.projection, slave, multipliers,
                                                          direction);
  };
  const linalg::Coupling normal = coupling(assembly::TraceDirection::normal);
  const linalg::Coupling b_m = setup.problem == PairingProblem::friction
                                   ? linalg::stack_rows(normal, coupling(assembly::TraceDirection::tangent))
                                   : normal;
  out.seconds_assembly += assembly_clock.seconds();
  Stopwatch primal_clock;
  const Eigen::MatrixXd s_m = master.gram_factor(setup.primal_norm).schur_complement(b_m);
  if (master.log()) master.log()->record("S_G (master)", s_m.rows(), s_m.cols(), primal_clock.seconds());
  out.s_g += s_m;
  out.seconds_primal += primal_clock.seconds();
  out.n_primal_dofs = master.n_dofs();
  out.h = master.whole_mesh().longest_edge();
  out.smallest_p = master.whole_mesh().smallest_degree();
}

// Elasticity: S_G = B A_G⁻¹ Bᵀ with B = B_n or (B_n; B_t) and A_G the Gram matrix of the primal
// norm on [S^p(T_h)]², every multiplier active; for a contact pair plus the master's share.
InfSupOperators elastic_infsup_operators(const InfSupSetup& setup) {
  const auto& elastic = *setup.elastic;
  HPC_VERIFY(!setup.mesh || elastic.built_on(*setup.mesh, setup.cell_degrees),
             "elastic operators of another mesh or degree distribution");
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  InfSupOperators out;
  const bool friction = setup.problem == PairingProblem::friction;
  Stopwatch assembly_clock;
  const auto& normal = elastic.coupling(multipliers, assembly::TraceDirection::normal);
  const linalg::Coupling coupling =
      friction ? linalg::stack_rows(normal, elastic.coupling(multipliers, assembly::TraceDirection::tangent)) : normal;
  out.seconds_assembly = assembly_clock.seconds();
  Stopwatch primal_clock;
  const auto& a_g = elastic.gram_factor(setup.primal_norm);
  Stopwatch schur_clock;
  out.s_g = a_g.schur_complement(coupling);
  if (elastic.log()) elastic.log()->record("S_G", out.s_g.rows(), out.s_g.cols(), schur_clock.seconds());
  out.seconds_primal = primal_clock.seconds();
  if (setup.master) add_master_pairing(setup, multipliers, out);
  out.gram_copies = friction ? 2 : 1;
  out.basis = pencil_basis(multipliers, setup.family, out.gram_copies);
  out.n_multiplier_dofs = static_cast<int>(out.basis.cols());
  out.s_g = restrict(out.s_g, out.basis);
  out.log = elastic.log();
  out.n_primal_dofs += elastic.n_dofs();
  out.h = std::max(out.h, elastic.whole_mesh().longest_edge());
  out.smallest_p = out.smallest_p > 0 ? std::min(out.smallest_p, elastic.whole_mesh().smallest_degree())
                                      : elastic.whole_mesh().smallest_degree();
  out.H = setup.boundary_mesh->mesh_size();
  return out;
}

}  // namespace

InfSupOperators assemble_infsup_operators(const InfSupSetup& setup) {
  HPC_VERIFY((setup.mesh || setup.primal || setup.elastic) && setup.boundary_mesh, "inf-sup setup without meshes");
  if (setup.elastic) return elastic_infsup_operators(setup);
  const bool friction = setup.problem == PairingProblem::friction;
  if (friction && !setup.friction_bound)
    throw InputError("the friction inf-sup problem (22) needs the friction bound s");

  InfSupOperators out;
  // A_G factorized with the whole Γ_C trace last: S_G comes from the factor's trailing block.
  std::unique_ptr<operators::PrimalOperators> own_primal;
  const operators::PrimalOperators& primal =
      operators::shared_or_own(setup.primal, setup.mesh, setup.cell_degrees, own_primal);
  const auto& space = primal.space();
  const auto& contact = primal.contact();
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  Stopwatch assembly_clock;  // (what is not built yet)
  const auto& coupling = primal.coupling(multipliers, friction ? setup.friction_bound : assembly::CouplingWeight{},
                                         friction ? "B^s" : "B");
  out.seconds_assembly = assembly_clock.seconds();
  Stopwatch primal_clock;
  const auto& a_g = primal.gram_factor();
  Stopwatch schur_clock;
  const Eigen::MatrixXd s_g = a_g.schur_complement(coupling);
  if (primal.log()) primal.log()->record("S_G", s_g.rows(), s_g.cols(), schur_clock.seconds());
  out.seconds_primal = primal_clock.seconds();

  const Eigen::SparseMatrix<double> all = pencil_basis(multipliers, setup.family, 1);
  out.basis = friction ? pencil_basis(multipliers, setup.family, 1,
                                      segments_meeting_support(contact, multipliers, setup.friction_bound.function()))
                       : all;
  if (out.basis.cols() == 0)
    throw InputError(fmt::format("{}: the friction bound s vanishes on all of Γ_C: no multiplier is left",
                                 setup.friction_bound.key().empty() ? "data.s" : setup.friction_bound.key()));
  out.s_g = restrict(s_g, out.basis);
  out.log = primal.log();
  out.n_primal_dofs = space.n_dofs();
  out.n_multiplier_dofs = static_cast<int>(all.cols());
  out.h = primal.whole_mesh().longest_edge();
  out.smallest_p = primal.whole_mesh().smallest_degree();
  out.H = setup.boundary_mesh->mesh_size();
  return out;
}

}  // namespace hpcontact::infsup
