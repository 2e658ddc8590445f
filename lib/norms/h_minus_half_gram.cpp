// interpolation_norm_gram and extension_norm_gram.
#include "norms/h_minus_half_gram.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <exception>
#include <numbers>
#include <thread>
#include <vector>

#include "assembly/coupling.hpp"
#include "assembly/poisson_assembly.hpp"
#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "mesh/refine.hpp"

namespace hpcontact::norms {

Eigen::MatrixXd inverse_sqrt_gram_dense(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& m,
                                        const Eigen::SparseMatrix<double>& c) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen{Eigen::MatrixXd(a), Eigen::MatrixXd(m)};
  if (eigen.info() != Eigen::Success)
    throw NumericalError("interpolation norm: the reference eigenproblem K_W Φ = M_W Φ Λ failed");
  const Eigen::MatrixXd scaled = eigen.eigenvectors().transpose() * c;  // Φᵀ C, shape (n_w, n_mult)
  const Eigen::VectorXd inverse_sqrt = eigen.eigenvalues().cwiseSqrt().cwiseInverse();
  return scaled.transpose() * inverse_sqrt.asDiagonal() * scaled;
}

Eigen::MatrixXd inverse_sqrt_gram_quadrature(const Eigen::SparseMatrix<double>& a,
                                             const Eigen::SparseMatrix<double>& m,
                                             const Eigen::SparseMatrix<double>& c, double lambda_max,
                                             bool split_over_ranks) {
  // Spectrum of (A, M) in [1, λ_max] (A − M = K_W ≥ 0). The trapezoidal rule over all of ℤ,
  //   ∫ e^s/(λ + e^{2s}) ds ≈ h Σ_k e^{s_k}/(λ + e^{2 s_k}),   s_k = s_lo + k h,
  // is spectrally accurate; nodes are computed on [s_lo, s_hi] = [−8, ½ log λ_max + 8], and the
  // nodes beyond sum in closed form, per eigenvalue λ,
  //   below: h Σ_{j≥1} e^{s_lo − jh}/λ = ρ e^{s_lo}/λ,   above: h Σ_{j≥1} e^{−s_hi − jh} = ρ e^{−s_hi},
  // ρ = h e^{−h}/(1 − e^{−h}), to relative errors e^{2 s_lo}/λ and λ e^{−2 s_hi} of terms that are
  // themselves ≤ e^{−8} of the total: about 1e-10 overall. (Truncating the integral instead, with
  // half weights at the ends, leaves an O(h² e^{−8}) Euler–Maclaurin error.) As operators the
  // tails are e^{s_lo} Cᵀ A⁻¹ C and e^{−s_hi} Cᵀ M⁻¹ C.
  constexpr double step = 0.35, margin = 8.0;
  const double s_lo = -margin, s_hi = 0.5 * std::log(lambda_max) + margin;
  const int n_nodes = static_cast<int>(std::ceil((s_hi - s_lo) / step)) + 1;
  const double h = (s_hi - s_lo) / (n_nodes - 1);
  const double tail = h * std::exp(-h) / (1.0 - std::exp(-h));
  const Eigen::MatrixXd c_dense = Eigen::MatrixXd(c);
  // W is one-dimensional: its matrices are banded after AMD, and a simplicial LDLᵀ of each is
  // cheap; most of the time goes into the solves with the n_mult columns of C. The nodes are
  // independent, so they run on up to kPartials threads; node k always adds into partial sum
  // k mod kPartials, summed in a fixed order, so the result does not depend on the thread count.
  // Split over the ranks, partial sum k is computed by rank k mod ranks alone (zero elsewhere)
  // and summed over the ranks: adding zeros is exact, so neither does it depend on the ranks.
  auto sandwich = [&](const Eigen::SparseMatrix<double>& matrix) {  // Cᵀ matrix⁻¹ C
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(matrix);
    if (factor.info() != Eigen::Success)
      throw NumericalError("interpolation norm: a shifted reference matrix K_W + t² M_W is not positive definite");
    return Eigen::MatrixXd(c.transpose() * factor.solve(c_dense));
  };
  constexpr int kPartials = 4;
  std::vector<Eigen::MatrixXd> partial(kPartials, Eigen::MatrixXd::Zero(c.cols(), c.cols()));
  std::vector<std::exception_ptr> failure(kPartials);
  auto accumulate = [&](int which) {
    try {
      for (int k = which; k < n_nodes; k += kPartials) {
        const double s = s_lo + k * h;
        partial[which] += h * std::exp(s) * sandwich(a + std::exp(2.0 * s) * m);
      }
    } catch (...) {
      failure[which] = std::current_exception();
    }
  };
  const auto [rank, ranks] = split_over_ranks ? mpi_rank_and_size() : std::pair{0, 1};
  std::vector<int> mine;
  for (int which = rank; which < kPartials; which += ranks) mine.push_back(which);
  // The ranks of one machine share its cores.
  const int threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()) / ranks, 1,
                                 std::max(1, static_cast<int>(mine.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (std::size_t k = t; k < mine.size(); k += threads) accumulate(mine[k]);
    });
  for (std::size_t k = 0; k < mine.size(); k += threads) accumulate(mine[k]);
  for (auto& thread : pool) thread.join();
  // A failure on one rank is agreed on by all, so that none waits in the sum.
  double failed = 0.0;
  for (const auto& error : failure) failed += error ? 1.0 : 0.0;
  if (ranks > 1) sum_over_ranks(&failed, 1);
  for (const auto& error : failure)
    if (error) std::rethrow_exception(error);
  if (failed != 0.0) throw NumericalError("interpolation norm: the quadrature failed on another rank");
  for (auto& sum : partial)
    if (ranks > 1) sum_over_ranks(sum.data(), sum.size());
  Eigen::MatrixXd integral = tail * (std::exp(s_lo) * sandwich(a) + std::exp(-s_hi) * sandwich(m));
  for (const auto& sum : partial) integral += sum;
  return (2.0 / std::numbers::pi) * integral;
}

Eigen::MatrixXd interpolation_norm_gram(const mesh::ContactBoundary& contact,
                                        const space::MultiplierSpace& multipliers,
                                        const InterpolationReference& reference) {
  if (reference.subdivisions < 1)
    throw_bad_input("interpolation norm", "subdivisions", std::to_string(reference.subdivisions),
                    "must be >= 1");
  const int q = reference.degree > 0 ? reference.degree : multipliers.max_degree() + 6;
  // W's mesh contains the breakpoints of T_{C,H}, so every W interval lies in one segment.
  std::vector<double> nodes;
  for (const auto& interval : assembly::common_intervals(contact, multipliers.boundary_mesh()))
    for (int k = 0; k < reference.subdivisions; ++k)
      nodes.push_back(interval.s_begin +
                      (interval.s_end - interval.s_begin) * k / reference.subdivisions);
  nodes.push_back(contact.length());
  const int n_intervals = static_cast<int>(nodes.size()) - 1;
  // Dofs: vertices 0..n_intervals, then q - 1 bubbles per interval.
  const int n_w = n_intervals + 1 + n_intervals * (q - 1);
  std::vector<Eigen::Triplet<double>> a_entries, m_entries, c_entries;
  double lambda_max = 1.0;  // max over intervals of λ_max(A_e, M_e) bounds λ_max(A_W, M_W)
  const int pc_max = multipliers.max_degree();
  const auto& rule = basis::gauss_legendre(basis::gauss_points_for_degree(2 * q + pc_max));
  const auto table = basis::tabulate_lobatto(q, rule.points);
  for (int k = 0; k < n_intervals; ++k) {
    std::vector<int> dofs{k, k + 1};
    for (int j = 2; j <= q; ++j) dofs.push_back(n_intervals + 1 + k * (q - 1) + (j - 2));
    const double half = 0.5 * (nodes[k + 1] - nodes[k]);
    const int segment = multipliers.boundary_mesh().segment_at(0.5 * (nodes[k] + nodes[k + 1]));
    const int first = multipliers.first_dof(segment), pc = multipliers.segment_degree(segment);
    Eigen::MatrixXd a_local = Eigen::MatrixXd::Zero(q + 1, q + 1), m_local = a_local;
    Eigen::MatrixXd c_local = Eigen::MatrixXd::Zero(q + 1, pc + 1);
    for (std::size_t g = 0; g < rule.points.size(); ++g) {
      const double w = rule.weights[g] * half;
      const double s = nodes[k] + half * (rule.points[g] + 1.0);
      const Eigen::VectorXd mu =
          multipliers.basis_values(segment, multipliers.local_coordinate(segment, s));
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
    lambda_max = std::max(lambda_max, Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(
                                          a_local, m_local, Eigen::EigenvaluesOnly)
                                          .eigenvalues()
                                          .maxCoeff());
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
  Eigen::MatrixXd gram = n_w <= reference.dense_limit
                             ? inverse_sqrt_gram_dense(stiffness_plus_mass, mass, coupling)
                             : inverse_sqrt_gram_quadrature(stiffness_plus_mass, mass, coupling, lambda_max,
                                                            reference.split_over_ranks);
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

ExtensionReferenceFactor::ExtensionReferenceFactor(const mesh::QuadMesh& mesh, const std::vector<int>& cell_degrees,
                                                   const ExtensionReference& reference) {
  if (reference.refinements < 0 || reference.extra_degree < 0)
    throw InputError("extension norm: refinements and extra_degree must be >= 0");
  fine_ = std::make_unique<mesh::QuadMesh>(mesh);
  std::vector<int> degrees = cell_degrees;
  for (int level = 0; level < reference.refinements; ++level) {
    *fine_ = mesh::refine_uniformly(*fine_);
    std::vector<int> children;
    for (int p : degrees) children.insert(children.end(), 4, p);  // children of cell c: 4c..4c+3
    degrees = std::move(children);
  }
  for (int& p : degrees) p += reference.extra_degree;
  operators_ = std::make_unique<PrimalOperators>(*fine_, std::move(degrees));
  operators_->gram_factor();
}

Eigen::MatrixXd extension_norm_gram(const ExtensionReferenceFactor& reference,
                                    const space::MultiplierSpace& multipliers) {
  const auto& reference_operators = reference.operators();
  return reference_operators.gram_factor().schur_complement(assembly::assemble_coupling(
      reference_operators.space(), reference_operators.contact(), multipliers));
}

Eigen::MatrixXd extension_norm_gram(const mesh::QuadMesh& mesh, const std::vector<int>& cell_degrees,
                                    const space::MultiplierSpace& multipliers,
                                    const ExtensionReference& reference) {
  return extension_norm_gram(ExtensionReferenceFactor(mesh, cell_degrees, reference), multipliers);
}

}  // namespace hpcontact::norms
