// analyse_infsup.
#include "infsup/infsup_analysis.hpp"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "infsup/generalized_eigen.hpp"
#include "mesh/contact_boundary.hpp"

namespace hpcontact::infsup {

EigenBackend parse_eigen_backend(const std::string& text, const std::string& origin) {
  if (text == "slepc") return EigenBackend::slepc;
  if (text == "dense") return EigenBackend::dense;
  throw_bad_input(origin, "eigensolver", text, "must be one of: slepc, dense");
}

namespace {

// The ranks the setup's operators (scalar or elastic) are factorized over; serial without any.
linalg::Distribution distribution_of(const InfSupSetup& setup) {
  if (setup.primal) return setup.primal->distribution();
  if (setup.elastic) return setup.elastic->distribution();
  return {};
}

std::unique_ptr<norms::GramLadder> own_ladder(const InfSupSetup& setup, const space::MultiplierSpace& multipliers) {
  if (setup.norm == GramNorm::interpolation)
    return std::make_unique<norms::GramLadder>(norms::interpolation_gram_ladder(multipliers));
  // (distributed, the first rank alone holds the whole mesh, which the references refine)
  return std::make_unique<norms::GramLadder>(
      norms::extension_gram_ladder(setup.mesh, setup.cell_degrees, multipliers, distribution_of(setup)));
}

// α of each zone's multipliers alone: the pencil (S_G, G) restricted to the active functions whose
// segments lie in the zone (every copy of the multiplier, for the elastic pairings).
std::vector<double> zone_alphas(const InfSupOperators& operators, const space::MultiplierSpace& multipliers,
                                const Eigen::MatrixXd& gram) {
  const auto& boundary = multipliers.boundary_mesh();
  const int n_zones = static_cast<int>(boundary.zones().size());
  if (n_zones < 2) return {};
  std::vector<int> zone_of_dof(multipliers.n_dofs());
  for (int k = 0; k < multipliers.n_segments(); ++k)
    for (int j = 0; j <= multipliers.segment_degree(k); ++j)
      zone_of_dof[multipliers.first_dof(k) + j] = boundary.zone_of_segment(k);
  // A function lives in one zone (the families do not cross zone ends): that of its first row.
  std::vector<int> zone_of_function;
  for (int c = 0; c < operators.basis.outerSize(); ++c) {
    Eigen::SparseMatrix<double>::InnerIterator it(operators.basis, c);
    zone_of_function.push_back(zone_of_dof[static_cast<std::size_t>(it.row() % multipliers.n_dofs())]);
  }
  std::vector<double> alphas;
  for (int z = 0; z < n_zones; ++z) {
    std::vector<int> rows;
    for (std::size_t i = 0; i < zone_of_function.size(); ++i)
      if (zone_of_function[i] == z) rows.push_back(static_cast<int>(i));
    if (rows.empty()) {
      alphas.push_back(std::numeric_limits<double>::quiet_NaN());  // no active multiplier (s ≡ 0 there)
      continue;
    }
    const auto sub = [&](const Eigen::MatrixXd& m) {
      Eigen::MatrixXd out(rows.size(), rows.size());
      for (std::size_t a = 0; a < rows.size(); ++a)
        for (std::size_t b = 0; b < rows.size(); ++b) out(a, b) = m(rows[a], rows[b]);
      return out;
    };
    alphas.push_back(std::sqrt(std::max(smallest_eigenpair_dense(sub(operators.s_g), sub(gram)).eigenvalue, 0.0)));
  }
  return alphas;
}

}  // namespace

LadderSolution smallest_on_ladder(const Eigen::MatrixXd& s_g, const Eigen::SparseMatrix<double>& basis, int gram_copies,
                                  const norms::GramLadder& grams, EigenBackend backend, double tolerance,
                                  linalg::Distribution distribution) {
  LadderSolution out;
  for (int level = 1;; ++level) {
    out.gram = restrict(block_copies(grams.at(level), gram_copies), basis);
    Stopwatch eigen_clock;
    out.pair = backend == EigenBackend::slepc ? smallest_eigenpair_slepc(s_g, out.gram)
                                              : smallest_eigenpair_dense(s_g, out.gram);
    out.seconds_eigen += eigen_clock.seconds();
    out.lambda_min = std::max(out.pair.eigenvalue, 0.0);
    out.alpha = std::sqrt(out.lambda_min);
    const Eigen::VectorXd& x = out.pair.eigenvector;
    const double fine_norm = x.dot(out.gram * x);
    const double coarse_norm = x.dot(restrict(block_copies(grams.at(level - 1), gram_copies), basis) * x);
    out.alpha_error = out.alpha * std::abs(std::sqrt(fine_norm / coarse_norm) - 1.0);
    out.reference_level = level;
    out.alpha_converged = grams.geometric() && out.alpha_error <= tolerance * out.alpha;
    int stop = out.alpha_converged || !grams.geometric() || level == grams.top_level();
    // A distributed ladder builds its next level collectively, so every rank takes rank 0's
    // decision. The sums over the ranks agree to the bit (sum_over_ranks); this guards the
    // ranks' own dense work, whose bits could still differ (e.g. another BLAS thread count).
    if (distribution.distributed()) MPI_Bcast(&stop, 1, MPI_INT, 0, distribution.ranks);
    if (stop) return out;
  }
}

InfSupResult analyse_infsup(const InfSupSetup& setup, EigenBackend backend) {
  if (!(setup.alpha_tolerance > 0.0 && setup.alpha_tolerance <= 0.1))
    throw_bad_input("inf-sup analysis", "alpha_tol", fmt::format("{}", setup.alpha_tolerance), "must be in (0, 0.1]");
  Stopwatch clock;
  const InfSupOperators operators = assemble_infsup_operators(setup);
  const space::MultiplierSpace multipliers(*setup.boundary_mesh, setup.segment_degrees);
  const std::unique_ptr<norms::GramLadder> own = setup.grams ? nullptr : own_ladder(setup, multipliers);
  const norms::GramLadder& grams = setup.grams ? *setup.grams : *own;
  const double seconds_gram_before = grams.seconds();
  InfSupResult result;
  const LadderSolution solved = smallest_on_ladder(operators.s_g, operators.basis, operators.gram_copies, grams,
                                                   backend, setup.alpha_tolerance, distribution_of(setup));
  const SmallestEigenpair& pair = solved.pair;
  const Eigen::MatrixXd& fine = solved.gram;
  result.alpha = solved.alpha;
  result.lambda_min = solved.lambda_min;
  result.alpha_error = solved.alpha_error;
  result.reference_level = solved.reference_level;
  result.alpha_converged = solved.alpha_converged;
  result.seconds_eigen = solved.seconds_eigen;
  result.zone_alpha = zone_alphas(operators, multipliers, fine);
  result.lambda_max = pair.largest_eigenvalue;
  result.singular = result.lambda_min <= kRoundOffZero * result.lambda_max;
  result.mode = operators.basis * pair.eigenvector;
  const int min_p = operators.smallest_p;
  const int max_pc = *std::max_element(setup.segment_degrees.begin(), setup.segment_degrees.end());
  result.pi = stability_indicator(operators.h, operators.H, min_p, max_pc);
  result.h = operators.h;
  result.H = operators.H;
  result.n_primal_dofs = operators.n_primal_dofs;
  result.n_multiplier_dofs = operators.n_multiplier_dofs;
  result.method = pair.method;
  result.residual = pair.residual;
  result.seconds_assembly = operators.seconds_assembly;
  result.seconds_primal = operators.seconds_primal;
  result.seconds_gram = grams.seconds() - seconds_gram_before;
  if (operators.log && result.seconds_gram > 0.0)
    operators.log->record(setup.norm == GramNorm::interpolation ? "G (interpolation norm)" : "G (extension norm)",
                          multipliers.n_dofs(), multipliers.n_dofs(), result.seconds_gram);
  result.seconds = clock.seconds();
  return result;
}

}  // namespace hpcontact::infsup
