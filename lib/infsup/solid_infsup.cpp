// α of 3-D pairings: S_G from A_G's trace-last factor, G from the surface interpolation ladder;
// by products on a distributed factor, led by its first rank.
#include "infsup/solid_infsup.hpp"

#include <fmt/format.h>

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <memory>
#include <set>

#include "assembly/solid_cell_system.hpp"
#include "assembly/solid_elastic_system.hpp"
#include "assembly/surface_coupling.hpp"
#include "contact/led_products.hpp"
#include "contact/schur_products.hpp"
#include "core/byte_buffer.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "infsup/surface_products_ladder.hpp"
#include "norms/surface_interpolation_gram.hpp"
#include "space/solid_vector_space.hpp"

namespace hpcontact::infsup {

namespace {

double longest_edge(const mesh::SolidMesh& mesh) {
  double out = 0.0;
  for (int e = 0; e < mesh.n_edges(); ++e)
    out = std::max(out, (mesh.vertex(mesh.edge(e)[1]) - mesh.vertex(mesh.edge(e)[0])).norm());
  return out;
}

double longest_side(const mesh::SurfaceMultiplierMesh& mesh) {
  double out = 0.0;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const auto [lo, hi] = mesh.cell_bounds(c);
    out = std::max(out, (hi - lo).maxCoeff());
  }
  return out;
}

/// R: the active multiplier functions, one column each: every nodal function for Signorini, those
/// of the cells of T_{C,H} that meet supp s for friction.
Eigen::SparseMatrix<double> active_functions(const SolidInfSupSetup& setup) {
  const space::SurfaceMultiplierSpace& multipliers = *setup.multipliers;
  std::vector<Eigen::Triplet<double>> entries;
  for (int c = 0; c < multipliers.mesh().n_cells(); ++c) {
    if (setup.problem == PairingProblem::friction &&
        !assembly::cell_meets_support(multipliers.mesh(), c, setup.friction_bound))
      continue;
    for (int k = 0; k < multipliers.per_cell(); ++k) {
      const int dof = multipliers.first_dof(c) + k;
      entries.emplace_back(dof, static_cast<int>(entries.size()), 1.0);
    }
  }
  if (entries.empty())
    throw InputError("the friction pairing (22): the bound s vanishes on every cell of T_{C,H} (s ≡ 0 on Γ_C)");
  Eigen::SparseMatrix<double> basis(multipliers.n_dofs(), static_cast<int>(entries.size()));
  basis.setFromTriplets(entries.begin(), entries.end());
  return basis;
}

Eigen::SparseMatrix<double> identity(int n) {
  Eigen::SparseMatrix<double> out(n, n);
  out.setIdentity();
  return out;
}

/// The elastic pairing's B: B_n (n the outward normal of Γ_C), then B_1 and B_2 along Γ_C's axes
/// when `copies` is 3, each multipliers.n_dofs() rows.
linalg::Coupling elastic_coupling(const SolidInfSupSetup& setup, int copies) {
  const auto& surface = setup.multipliers->mesh().surface();
  const linalg::Coupling scalar = assembly::surface_coupling(setup.vector_space->scalar(), *setup.multipliers);
  const std::array<Eigen::Vector3d, 3> directions{surface.normal(), surface.axis(0), surface.axis(1)};
  std::vector<Eigen::Triplet<double>> entries;
  for (int k = 0; k < copies; ++k) {
    const linalg::Coupling part = assembly::directional_coupling(*setup.vector_space, scalar, directions[k]);
    for (int row = 0; row < part.outerSize(); ++row)
      for (linalg::Coupling::InnerIterator it(part, row); it; ++it)
        entries.emplace_back(k * static_cast<int>(scalar.rows()) + row, static_cast<int>(it.col()), it.value());
  }
  linalg::Coupling b(copies * scalar.rows(), setup.vector_space->n_dofs());
  b.setFromTriplets(entries.begin(), entries.end());
  return b;
}

/// The products ladder's solution as bytes (its G is never formed) and back.
std::vector<char> ladder_bytes(const LadderSolution& solved) {
  ByteWriter out;
  const SmallestEigenpair& pair = solved.pair;
  out.put(pair.eigenvalue);
  out.put(std::vector<double>(pair.eigenvector.data(), pair.eigenvector.data() + pair.eigenvector.size()));
  out.put(pair.largest_eigenvalue);
  out.put(pair.iterations);
  out.put(pair.residual);
  out.put(pair.method);
  for (double value : {solved.alpha, solved.lambda_min, solved.alpha_error, solved.seconds_eigen}) out.put(value);
  out.put(solved.reference_level);
  out.put(static_cast<char>(solved.alpha_converged));
  return out.take();
}
LadderSolution ladder_of_bytes(const std::vector<char>& bytes) {
  ByteReader in(bytes);
  LadderSolution solved;
  SmallestEigenpair& pair = solved.pair;
  pair.eigenvalue = in.get<double>();
  const auto vector = in.get_vector<double>();
  pair.eigenvector = Eigen::Map<const Eigen::VectorXd>(vector.data(), static_cast<Eigen::Index>(vector.size()));
  pair.largest_eigenvalue = in.get<double>();
  pair.iterations = in.get<int>();
  pair.residual = in.get<double>();
  pair.method = in.get_string();
  for (double* value : {&solved.alpha, &solved.lambda_min, &solved.alpha_error, &solved.seconds_eigen})
    *value = in.get<double>();
  solved.reference_level = in.get<int>();
  solved.alpha_converged = in.get<char>() != 0;
  HPC_VERIFY(in.at_end(), "bytes of a ladder solution left over");
  return solved;
}

/// The products ladder on S_G: on a distributed factor the first rank runs it and the others serve
/// its products (contact/led_products.hpp), so that no rank can take a step the others do not.
LadderSolution products_ladder(const SolidInfSupSetup& setup, const assembly::CondensedFactor& factor,
                               const contact::TraceOperator& s_g, const Eigen::SparseMatrix<double>& basis,
                               int copies) {
  const auto run = [&](const contact::TraceOperator& s) {
    return smallest_on_products_ladder(s, basis, copies, *setup.multipliers, setup.alpha_tolerance);
  };
  if (!factor.distribution().distributed()) return run(s_g);
  return ladder_of_bytes(contact::run_with_products_led_by_first_rank(
      s_g, factor.distribution().ranks, [&](const contact::TraceOperator& s) { return ladder_bytes(run(s)); }));
}

/// Stage 3 of analyse_solid_infsup: the ladder on S_G and G dense (setup.grams or its own), or by
/// products; the seconds of S_G (from `phase`'s start), G and the eigensolves into `result`.
LadderSolution solve_pencil(const SolidInfSupSetup& setup, const assembly::CondensedFactor& factor,
                            const linalg::Coupling& b, const Eigen::SparseMatrix<double>& basis, int copies,
                            bool products, EigenBackend backend, const Stopwatch& phase, InfSupResult& result) {
  const space::SurfaceMultiplierSpace& multipliers = *setup.multipliers;
  LadderSolution solved;
  if (products) {
    const contact::TraceOperator s_g = contact::schur_products(factor, b);
    result.seconds_primal = phase.seconds();
    solved = products_ladder(setup, factor, s_g, basis, copies);
  } else {
    const Eigen::MatrixXd s_g = restrict(factor.schur_complement(b), basis);
    result.seconds_primal = phase.seconds();
    std::unique_ptr<norms::GramLadder> own_ladder;
    if (!setup.grams)
      own_ladder = std::make_unique<norms::GramLadder>(norms::surface_interpolation_gram_ladder(multipliers));
    const norms::GramLadder& grams = setup.grams ? *setup.grams : *own_ladder;
    const double seconds_gram_before = grams.seconds();
    solved = smallest_on_ladder(s_g, basis, copies, grams, backend, setup.alpha_tolerance);
    result.seconds_gram = grams.seconds() - seconds_gram_before;
  }
  result.seconds_eigen = solved.seconds_eigen;
  return solved;
}

}  // namespace

assembly::CondensedFactor solid_gram_factor(const space::SolidVectorSpace& space,
                                            const mesh::FlatContactSurface& surface, bool trace_last,
                                            linalg::Distribution distribution) {
  std::set<int> trace;
  for (const auto& face : surface.faces())
    for (const int scalar : space::dofs_on_face(space.scalar(), face))
      for (int c = 0; c < 3; ++c)
        if (const int dof = space.dof(scalar, c); dof >= 0) trace.insert(dof);
  return assembly::CondensedFactor(
      std::make_unique<assembly::SolidElasticCellSystem>(assembly::SolidElasticCellSystem::vector_h1(space)),
      trace_last ? std::vector<int>(trace.begin(), trace.end()) : std::vector<int>(), std::move(distribution));
}

assembly::CondensedFactor solid_gram_factor(const space::SolidH1Space& space, const mesh::FlatContactSurface& surface,
                                            bool trace_last, linalg::Distribution distribution) {
  std::set<int> trace;
  for (const auto& face : surface.faces())
    for (const int dof : space::dofs_on_face(space, face)) trace.insert(dof);
  return assembly::CondensedFactor(std::make_unique<assembly::SolidScalarCellSystem>(space, 1.0, 1.0),
                                   trace_last ? std::vector<int>(trace.begin(), trace.end()) : std::vector<int>(),
                                   std::move(distribution));
}

InfSupResult analyse_solid_infsup(const SolidInfSupSetup& setup, EigenBackend backend) {
  if (!(setup.alpha_tolerance > 0.0 && setup.alpha_tolerance <= 0.1))
    throw_bad_input("inf-sup analysis", "alpha_tol", fmt::format("{}", setup.alpha_tolerance), "must be in (0, 0.1]");
  HPC_VERIFY(setup.space && setup.multipliers, "analyse_solid_infsup: the space or the multipliers are missing");
  if (!setup.multipliers->mesh().is_grid())
    throw InputError(
        "α of a 3-D pairing needs a grid T_{C,H}: its interpolation norm is computed from the cosine moments of "
        "tensor multipliers, which triangles do not have");
  if (setup.problem == PairingProblem::friction && !setup.friction_bound && !setup.vector_space)
    throw InputError("the friction pairing (22) needs the friction bound s (data.s)");
  const space::SolidH1Space& space = *setup.space;
  const space::SurfaceMultiplierSpace& multipliers = *setup.multipliers;
  Stopwatch clock;
  InfSupResult result;

  // 1. B (B^s for friction; the elastic pairings' rows of B_n, B_1, B_2) and the active multiplier
  // functions R.
  Stopwatch phase;
  const bool elastic = setup.vector_space != nullptr;
  const int copies = elastic && setup.problem == PairingProblem::friction ? 3 : 1;
  const linalg::Coupling b =
      elastic ? elastic_coupling(setup, copies)
              : assembly::surface_coupling(
                    space, multipliers,
                    setup.problem == PairingProblem::friction ? setup.friction_bound : assembly::SolidFunction());
  const Eigen::SparseMatrix<double> basis = elastic ? identity(copies * multipliers.n_dofs()) : active_functions(setup);
  result.seconds_assembly = phase.seconds();

  // 2. A_G's factor; 3. the smallest eigenpair on G's ladder, S_G and G dense or by products.
  phase = Stopwatch();
  // (a ladder given by the caller is one of dense G: `automatic` keeps it)
  const bool products = uses_alpha_products(setup.path, b.rows(), backend) &&
                        (setup.grams == nullptr || setup.path == contact::SchurPath::products);
  HPC_VERIFY(!(products && setup.grams), "analyse_solid_infsup: a ladder of dense G given to the products path");
  std::unique_ptr<assembly::CondensedFactor> own_factor;
  if (!setup.gram_factor) {
    // (the products need no trailing trace block: they solve on the skeleton)
    const bool trace_last = !products;
    own_factor = std::make_unique<assembly::CondensedFactor>(
        elastic ? solid_gram_factor(*setup.vector_space, multipliers.mesh().surface(), trace_last, setup.distribution)
                : solid_gram_factor(space, multipliers.mesh().surface(), trace_last, setup.distribution));
  }
  const assembly::CondensedFactor& factor = setup.gram_factor ? *setup.gram_factor : *own_factor;
  const LadderSolution solved = solve_pencil(setup, factor, b, basis, copies, products, backend, phase, result);
  result.alpha = solved.alpha;
  result.lambda_min = solved.lambda_min;
  result.alpha_error = solved.alpha_error;
  result.reference_level = solved.reference_level;
  result.alpha_converged = solved.alpha_converged;
  result.lambda_max = solved.pair.largest_eigenvalue;
  result.singular = result.lambda_min <= kRoundOffZero * result.lambda_max;
  result.mode = basis * solved.pair.eigenvector;
  result.method = solved.pair.method;
  result.residual = solved.pair.residual;

  // 4. What the record reports of the pairing.
  result.h = longest_edge(space.mesh());
  result.H = longest_side(multipliers.mesh());
  int smallest_p = space.cell_degree(0);
  for (int c = 0; c < space.mesh().n_cells(); ++c) smallest_p = std::min(smallest_p, space.cell_degree(c));
  result.pi = stability_indicator(result.h, result.H, smallest_p, multipliers.degree());
  result.n_primal_dofs = elastic ? setup.vector_space->n_dofs() : space.n_dofs();
  result.n_multiplier_dofs = copies * multipliers.n_dofs();
  result.seconds = clock.seconds();
  return result;
}

}  // namespace hpcontact::infsup
