// ProjectedConjugateGradients: the constrained start, W and E, and the CG loop with the
// projected preconditioner.
#include "linalg/projected_cg.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_session.hpp"

namespace hpcontact::linalg {

namespace {

void copy_into(const Eigen::VectorXd& x, Vec v) {
  PetscScalar* array = nullptr;
  HPC_PETSC_CALL(VecGetArray(v, &array));
  std::copy(x.data(), x.data() + x.size(), array);
  HPC_PETSC_CALL(VecRestoreArray(v, &array));
}

Eigen::VectorXd copy_from(Vec v, Eigen::Index size) {
  const PetscScalar* array = nullptr;
  HPC_PETSC_CALL(VecGetArrayRead(v, &array));
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(array, size);
  HPC_PETSC_CALL(VecRestoreArrayRead(v, &array));
  return out;
}

}  // namespace

ProjectedConjugateGradients::ProjectedConjugateGradients(MPI_Comm ranks, Mat a, PC pc,
                                                         Eigen::SparseMatrix<double> owned_constraints,
                                                         int max_iterations, std::string name)
    : ranks_(ranks),
      a_(a),
      pc_(pc),
      constraints_(std::move(owned_constraints)),
      max_iterations_(max_iterations),
      name_(std::move(name)) {
  HPC_PETSC_CALL(MatCreateVecs(a_, in_.out(), out_.out()));
  PetscInt owned = 0;
  HPC_PETSC_CALL(VecGetLocalSize(in_.get(), &owned));
  HPC_VERIFY(constraints_.rows() == owned, "constraints not at the operator's owned rows");
  HPC_PETSC_CALL(MatGetDiagonal(a_, in_.get()));
  diagonal_inverse_ = copy_from(in_.get(), owned).cwiseInverse();
}

Eigen::VectorXd ProjectedConjugateGradients::precondition(const Eigen::VectorXd& x) const {
  copy_into(x, in_.get());
  HPC_PETSC_CALL(PCApply(pc_, in_.get(), out_.get()));
  return copy_from(out_.get(), x.size());
}

Eigen::VectorXd ProjectedConjugateGradients::multiply(const Eigen::VectorXd& x) const {
  copy_into(x, in_.get());
  HPC_PETSC_CALL(MatMult(a_, in_.get(), out_.get()));
  return copy_from(out_.get(), x.size());
}

double ProjectedConjugateGradients::sum(double local) const {
  MPI_Allreduce(MPI_IN_PLACE, &local, 1, MPI_DOUBLE, MPI_SUM, ranks_);
  return local;
}

Eigen::VectorXd ProjectedConjugateGradients::sum(Eigen::VectorXd local) const {
  sum_over_ranks(ranks_, local.data(), static_cast<std::size_t>(local.size()));
  return local;
}

ProjectedConjugateGradients::ActiveRows ProjectedConjugateGradients::active_rows(const std::vector<int>& active) const {
  // C_Aᵀ (owned × k), W = D⁻¹ C_Aᵀ and E = C_A W, Cholesky-factorized.
  ActiveRows out;
  Eigen::SparseMatrix<double>& c_active = out.c;
  c_active.resize(constraints_.rows(), static_cast<Eigen::Index>(active.size()));
  {
    std::vector<Eigen::Triplet<double>> entries;
    for (std::size_t k = 0; k < active.size(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(constraints_, active[k]); it; ++it)
        entries.emplace_back(static_cast<int>(it.row()), static_cast<int>(k), it.value());
    c_active.setFromTriplets(entries.begin(), entries.end());
  }
  out.w = diagonal_inverse_.asDiagonal() * c_active;
  Eigen::MatrixXd e = Eigen::MatrixXd(c_active.transpose() * out.w);
  sum_over_ranks(ranks_, e.data(), static_cast<std::size_t>(e.size()));
  e = 0.5 * (e + e.transpose());
  out.e.compute(e);
  if (e.rows() > 0) {
    const double smallest = out.e.matrixL().toDenseMatrix().diagonal().minCoeff();
    const double largest = std::sqrt(e.diagonal().maxCoeff());
    if (out.e.info() != Eigen::Success || !(smallest > 1e-8 * largest))
      throw NumericalError(
          fmt::format("{}: the {} active constraints are linearly dependent (C D⁻¹ Cᵀ is singular: "
                      "smallest Cholesky pivot {:.3e} of {:.3e}): more active multipliers than the "
                      "trace separates, an unstable pairing; a higher p or a coarser T_{{C,H}} "
                      "removes them",
                      name_, active.size(), smallest, largest));
  }
  return out;
}

ConstrainedSolution ProjectedConjugateGradients::solve(const Eigen::VectorXd& owned_rhs, const std::vector<int>& active,
                                                       const Eigen::VectorXd& values,
                                                       const Eigen::VectorXd& owned_start, double relative_tolerance) {
  const Eigen::Index owned = constraints_.rows();
  HPC_VERIFY(owned_rhs.size() == owned && owned_start.size() == owned, "vectors not at the owned rows");
  HPC_VERIFY(static_cast<Eigen::Index>(active.size()) == values.size(), "one value per active row");
  for (std::size_t k = 0; k < active.size(); ++k)
    HPC_VERIFY(active[k] >= 0 && active[k] < constraints_.cols() && (k == 0 || active[k] > active[k - 1]),
               "active rows not ascending within C");
  const ActiveRows rows = active_rows(active);
  const Eigen::SparseMatrix<double>& c_active = rows.c;
  const Eigen::SparseMatrix<double>& w = rows.w;
  const Eigen::LLT<Eigen::MatrixXd>& e_factor = rows.e;
  // E⁻¹ C_A y (each rank its rows' part of C_A y), and Π y = y − W E⁻¹ C_A y.
  auto constraint_part = [&](const Eigen::VectorXd& y) -> Eigen::VectorXd {
    return e_factor.solve(sum(Eigen::VectorXd(c_active.transpose() * y)));
  };
  auto projected = [&](Eigen::VectorXd y) {
    if (!active.empty()) y -= w * constraint_part(y);
    return y;
  };

  // The start on C_A x = c_A: x += W E⁻¹ (c_A − C_A x).
  ConstrainedSolution out;
  Eigen::VectorXd x = owned_start;
  if (!active.empty()) x += w * e_factor.solve(values - sum(Eigen::VectorXd(c_active.transpose() * x)));
  // r is kept as the KKT residual b − A x − C_Aᵀ μ: each residual's multipliers δ = E⁻¹ C_A D⁻¹ r
  // are moved out of it (r ← Πᵀ r), so that (r, z) is a form of a small r (with r = b − A x it
  // would be the difference of two large terms, which cancel to round-off at a relative residual
  // of 1e-9), and z = Π M⁻¹ r.
  Eigen::VectorXd mu = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(active.size()));
  Eigen::VectorXd r = owned_rhs - multiply(x), z;
  auto project = [&] {
    if (!active.empty()) {
      const Eigen::VectorXd delta = constraint_part(Eigen::VectorXd(diagonal_inverse_.cwiseProduct(r)));
      mu += delta;
      r -= c_active * delta;
    }
    z = projected(precondition(r));
  };
  // ‖z‖ = ‖Π M⁻¹ (b − A x − C_Aᵀ μ)‖ against ‖Π M⁻¹ (b − C_Aᵀ μ)‖, the latter (one more
  // application of M⁻¹) at the start and wherever the former passes the test with the last one.
  double scale = 0.0;
  auto measure_scale = [&] {
    const Eigen::VectorXd load = owned_rhs - c_active * mu;
    scale = std::sqrt(sum(projected(precondition(load)).squaredNorm()));
    ++applications_;
  };
  auto converged = [&] {
    const double residual = std::sqrt(sum(z.squaredNorm()));
    auto ratio = [&] { return scale > 0.0 ? residual / scale : (residual > 0.0 ? 1.0 : 0.0); };
    out.relative_residual = ratio();
    if (out.relative_residual > relative_tolerance) return false;
    measure_scale();
    out.relative_residual = ratio();
    return out.relative_residual <= relative_tolerance;
  };
  project();
  measure_scale();
  Eigen::VectorXd p = z;
  double rho = sum(r.dot(z));
  while (!converged()) {
    if (out.iterations == max_iterations_)
      throw NumericalError(
          fmt::format("{}: projected conjugate gradients did not converge in {} iterations (relative "
                      "residual {:.3e}, tolerance {:.1e}); raise the solver's ksp_max_it",
                      name_, max_iterations_, out.relative_residual, relative_tolerance));
    const Eigen::VectorXd q = multiply(p);
    const double curvature = sum(p.dot(q));
    if (!(curvature > 0.0))
      throw NumericalError(
          fmt::format("{}: projected conjugate gradients met pᵀ A p = {:.3e} at iteration {}: the "
                      "matrix is not positive definite on the constraints' null space",
                      name_, curvature, out.iterations));
    const double step = rho / curvature;
    x += step * p;
    r -= step * q;
    project();
    ++out.iterations;
    const double rho_next = sum(r.dot(z));
    if (!(rho_next > 0.0)) {
      // (round-off near convergence: a preconditioner symmetric only to rounding may give a zero
      // or negative (r, z); judged by the residual as PETSc's CG stops are)
      if (converged() || out.relative_residual <= 100 * relative_tolerance) break;
      throw NumericalError(
          fmt::format("{}: the preconditioner is not positive definite ((r, z) = {:.3e} at "
                      "iteration {}, relative residual {:.3e})",
                      name_, rho_next, out.iterations, out.relative_residual));
    }
    p = z + (rho_next / rho) * p;
    rho = rho_next;
  }
  iterations_ += out.iterations;
  out.x = std::move(x);
  out.multipliers = std::move(mu);
  return out;
}

}  // namespace hpcontact::linalg
