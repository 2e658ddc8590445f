// CondensedFactor: per-cell elimination of the interior modes (shared between congruent
// parallelograms), assembly of the skeleton Schur complement S (lower triangle), CHOLMOD on S.
#include "assembly/condensed_factor.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <map>
#include <optional>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "mesh/cell_partition.hpp"

namespace hpcontact::assembly {

/// The elimination of one cell's interior modes, with the dofs' signs taken out (a cell's
/// signs are D = diag(sign_s); its element matrix is D A_T D, interior signs are all +1).
struct CondensedFactor::CellBlock {
  std::vector<int> skeleton, interior;          ///< local shape indices
  Eigen::LLT<Eigen::MatrixXd> interior_factor;  ///< A_ii = L Lᵀ
  Eigen::MatrixXd interior_solve;               ///< A_ii⁻¹ A_is, shape (n_interior, n_skeleton_local)
  Eigen::MatrixXd schur;                        ///< S_T = A_ss − A_si A_ii⁻¹ A_is
};

namespace {

// Tells the user (once per process, on rank 0) when substructuring's dense interface problem
// outweighs the ranks' factors: adding ranks then costs memory per rank instead of saving it.
void note_if_interface_dominates(const linalg::SubstructuredCholesky& factor) {
  static bool noted = false;
  if (noted || mpi_rank_and_size().first != 0 ||
      !linalg::interface_outweighs_factors(factor.interface_size(), factor.mean_factor_nonzeros()))
    return;
  noted = true;
  const double g = factor.interface_size();
  fmt::print(stderr,
             "hpcontact: note: substructuring's dense interface problem ({} unknowns between the parts (and Γ_C), "
             "{:.0f} MB on every rank) outweighs the ranks' sparse factors ({:.0f} MB on average): more ranks raise "
             "the memory per rank; --distributed-solver mumps or bddc hold no interface matrix\n",
             factor.interface_size(), g * g * 8e-6, factor.mean_factor_nonzeros() * 8e-6);
}

// Rows of `values` (global dof order) at a cell's interior unknowns `local`.
Eigen::MatrixXd interior_rows(const std::vector<CellDof>& dofs, const std::vector<int>& local,
                              const Eigen::Ref<const Eigen::MatrixXd>& values) {
  Eigen::MatrixXd out(local.size(), values.cols());
  for (std::size_t k = 0; k < local.size(); ++k) out.row(k) = values.row(dofs[local[k]].dof);
  return out;
}

// Rows of `values` at a cell's skeleton unknowns `local`, times their signs (0 for Dirichlet
// dofs): the coefficients of the cell's unsigned element block.
Eigen::MatrixXd signed_skeleton_rows(const std::vector<CellDof>& dofs, const std::vector<int>& local,
                                     const Eigen::Ref<const Eigen::MatrixXd>& values) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(local.size(), values.cols());
  for (std::size_t s = 0; s < local.size(); ++s)
    if (const auto& dof = dofs[local[s]]; dof.dof >= 0) out.row(s) = dof.sign * values.row(dof.dof);
  return out;
}

}  // namespace

CondensedFactor::CondensedFactor(const space::H1Space& space, double stiffness_weight, double mass_weight,
                                 const std::vector<int>& trailing, linalg::Distribution distribution,
                                 const std::vector<int>& part_of_cell)
    : CondensedFactor(std::make_unique<ScalarCellSystem>(space, stiffness_weight, mass_weight), trailing, distribution,
                      part_of_cell) {}

CondensedFactor::CondensedFactor(std::unique_ptr<const CellSystem> system, const std::vector<int>& trailing,
                                 linalg::Distribution distribution, const std::vector<int>& part_of_cell)
    : system_(std::move(system)),
      size_(system_->n_dofs()),
      n_trailing_(static_cast<int>(trailing.size())),
      distribution_(distribution) {
  for (int index : trailing)
    HPC_VERIFY(index >= 0 && index < system_->n_skeleton_dofs(), "trailing set outside the skeleton dofs");
  const int n_cells = system_->mesh().n_cells(), n_skeleton = system_->n_skeleton_dofs();
  std::vector<char> contributes(n_cells, 1);
  const bool distributed = distribution.distributed();
  MPI_Comm ranks = distribution.ranks;
  if (distributed) {
    const int rank = rank_and_size(ranks).first;
    HPC_VERIFY(part_of_cell.empty() || static_cast<int>(part_of_cell.size()) == n_cells, "one part per cell");
    const std::vector<int> parts =
        part_of_cell.empty() ? mesh::split_cells_over_ranks(system_->mesh(), cell_work_weights(*system_), ranks)
                             : part_of_cell;
    for (int c = 0; c < n_cells; ++c) contributes[c] = parts[c] == rank;
  }
  // Distributed, a degenerate cell fails on the rank that owns it: every rank ends the same way.
  // (Serial factors may be built by one rank alone, e.g. a sweep's points: no collective then.)
  std::vector<Eigen::Triplet<double>> lower;
  if (distributed)
    run_on_all_ranks_agreeing([&] { lower = eliminate_interiors(contributes); }, ranks);
  else
    lower = eliminate_interiors(contributes);
  switch (distribution.solver) {
    case linalg::DistributedSolver::serial: {
      Eigen::SparseMatrix<double> schur(n_skeleton, n_skeleton);
      schur.setFromTriplets(lower.begin(), lower.end());
      lower = {};
      serial_ = std::make_unique<linalg::SparseCholesky>(schur, trailing);
      break;
    }
    case linalg::DistributedSolver::substructuring:
      substructured_ = std::make_unique<linalg::SubstructuredCholesky>(ranks, n_skeleton, lower, trailing);
      note_if_interface_dominates(*substructured_);
      break;
    case linalg::DistributedSolver::mumps:
      mumps_ = std::make_unique<linalg::DistributedCholesky>(ranks, n_skeleton, lower, trailing);
      break;
    case linalg::DistributedSolver::bddc:
      bddc_ = std::make_unique<linalg::BddcSolver>(ranks, n_skeleton, lower);
      break;
  }
}

std::vector<Eigen::Triplet<double>> CondensedFactor::eliminate_interiors(const std::vector<char>& contributes) {
  const CellSystem& system = *system_;
  const int n_cells = system.mesh().n_cells();
  std::map<CongruenceKey, int> congruent;
  block_of_cell_.assign(n_cells, -1);
  std::vector<Eigen::Triplet<double>> lower;
  std::vector<CellDof> dofs;
  for (int c = 0; c < n_cells; ++c) {
    if (!contributes[c]) continue;  // another rank's cell: eliminated there
    system.cell_dofs(c, dofs);
    const std::optional<CongruenceKey> key = system.congruence_key(c);
    if (key)
      if (const auto found = congruent.find(*key); found != congruent.end()) block_of_cell_[c] = found->second;
    if (block_of_cell_[c] < 0) {
      const int n = static_cast<int>(dofs.size());
      Eigen::VectorXd sign(n);
      for (int s = 0; s < n; ++s) sign(s) = dofs[s].sign;
      const Eigen::MatrixXd a = sign.asDiagonal() * system.element_matrix(c) * sign.asDiagonal();
      auto block = std::make_unique<CellBlock>();
      for (int s = 0; s < n; ++s) (dofs[s].interior ? block->interior : block->skeleton).push_back(s);
      const Eigen::MatrixXd a_ss = a(block->skeleton, block->skeleton);
      if (block->interior.empty()) {
        block->schur = a_ss;
      } else {
        block->interior_factor.compute(a(block->interior, block->interior));
        if (block->interior_factor.info() != Eigen::Success)
          throw NumericalError(fmt::format(
              "static condensation: the interior block of cell {} is not positive definite (degenerate cell?)", c));
        block->interior_solve = block->interior_factor.solve(Eigen::MatrixXd(a(block->interior, block->skeleton)));
        block->schur = a_ss - a(block->skeleton, block->interior) * block->interior_solve;
      }
      block_of_cell_[c] = static_cast<int>(blocks_.size());
      if (key) congruent.emplace(*key, block_of_cell_[c]);
      blocks_.push_back(std::move(block));
    }
    const CellBlock& block = *blocks_[block_of_cell_[c]];
    // The lower triangle (all CHOLMOD reads); exact zeros (Lobatto orthogonality on
    // parallelograms) stay out of the pattern.
    for (std::size_t t = 0; t < block.skeleton.size(); ++t) {
      const auto& column = dofs[block.skeleton[t]];
      if (column.dof < 0) continue;
      for (std::size_t s = 0; s < block.skeleton.size(); ++s) {
        const auto& row = dofs[block.skeleton[s]];
        const double value = block.schur(s, t);
        if (row.dof >= column.dof && value != 0.0)
          lower.emplace_back(row.dof, column.dof, row.sign * column.sign * value);
      }
    }
  }
  return lower;
}

CondensedFactor::~CondensedFactor() = default;
CondensedFactor::CondensedFactor(CondensedFactor&&) noexcept = default;
CondensedFactor& CondensedFactor::operator=(CondensedFactor&&) noexcept = default;

Eigen::MatrixXd CondensedFactor::skeleton_solve(const Eigen::MatrixXd& rhs) const {
  if (serial_) return serial_->solve(rhs);
  if (bddc_) return bddc_->solve(rhs);
  return substructured_ ? substructured_->solve(rhs) : mumps_->solve(rhs);
}

Eigen::MatrixXd CondensedFactor::condense(const Eigen::MatrixXd& rhs) const {
  // Each rank subtracts its own cells' corrections; distributed, they are summed over the ranks.
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n_skeleton(), rhs.cols());
  std::vector<CellDof> dofs;
  for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
    if (block_of_cell_[c] < 0) continue;
    const CellBlock& block = *blocks_[block_of_cell_[c]];
    if (block.interior.empty()) continue;
    system_->cell_dofs(c, dofs);
    // (A_ii⁻¹ A_is)ᵀ f_i
    const Eigen::MatrixXd correction = block.interior_solve.transpose() * interior_rows(dofs, block.interior, rhs);
    for (std::size_t s = 0; s < block.skeleton.size(); ++s) {
      const auto& dof = dofs[block.skeleton[s]];
      if (dof.dof >= 0) out.row(dof.dof) -= dof.sign * correction.row(s);
    }
  }
  if (distribution_.distributed()) sum_over_ranks(distribution_.ranks, out.data(), out.size());
  return out + rhs.topRows(n_skeleton());
}

Eigen::MatrixXd CondensedFactor::solve(const Eigen::MatrixXd& rhs) const {
  HPC_VERIFY(rhs.rows() == size_, "right-hand side of the wrong size");
  Eigen::MatrixXd out(size_, rhs.cols());
  const int n_skeleton = this->n_skeleton();
  out.topRows(n_skeleton) = skeleton_solve(condense(rhs));
  // Each rank recovers its own cells' interior modes (the unknowns after the skeleton, each in one
  // cell); distributed, the other ranks' are summed in.
  Eigen::MatrixXd interiors = Eigen::MatrixXd::Zero(size_ - n_skeleton, rhs.cols());
  std::vector<CellDof> dofs;
  for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
    if (block_of_cell_[c] < 0) continue;
    const CellBlock& block = *blocks_[block_of_cell_[c]];
    if (block.interior.empty()) continue;
    system_->cell_dofs(c, dofs);
    const Eigen::MatrixXd interior = block.interior_factor.solve(interior_rows(dofs, block.interior, rhs)) -
                                     block.interior_solve * signed_skeleton_rows(dofs, block.skeleton, out);
    for (std::size_t k = 0; k < block.interior.size(); ++k)
      interiors.row(dofs[block.interior[k]].dof - n_skeleton) = interior.row(k);
  }
  if (distribution_.distributed()) sum_over_ranks(distribution_.ranks, interiors.data(), interiors.size());
  out.bottomRows(size_ - n_skeleton) = interiors;
  return out;
}

Eigen::VectorXd CondensedFactor::solve(const Eigen::VectorXd& rhs) const { return solve(Eigen::MatrixXd(rhs)).col(0); }

Eigen::MatrixXd CondensedFactor::schur_complement(const Eigen::SparseMatrix<double>& b) const {
  HPC_VERIFY(b.cols() == size_, "B A⁻¹ Bᵀ: B has the wrong number of columns");
  const int n_skeleton = this->n_skeleton();
  bool skeleton_only = true;
  for (int col = n_skeleton; skeleton_only && col < b.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(b, col); it; ++it)
      if (it.value() != 0.0) skeleton_only = false;
  if (skeleton_only) {
    const Eigen::SparseMatrix<double> b_skeleton = b.leftCols(n_skeleton);
    if (serial_) return serial_->schur_complement(b_skeleton);
    if (bddc_) return bddc_->schur_complement(b_skeleton);
    return substructured_ ? substructured_->schur_complement(b_skeleton) : mumps_->schur_complement(b_skeleton);
  }
  const Eigen::MatrixXd result = b * solve(Eigen::MatrixXd(b.transpose()));
  return 0.5 * (result + result.transpose());
}

double CondensedFactor::quadratic_form(const Eigen::VectorXd& u) const {
  HPC_VERIFY(u.size() == size_, "quadratic form of a vector of the wrong size");
  // uᵀ A u = Σ_T u_sᵀ S_T u_s + ‖Lᵀ (u_i + A_ii⁻¹ A_is u_s)‖², per cell with its signs.
  double sum = 0.0;
  std::vector<CellDof> dofs;
  for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
    if (block_of_cell_[c] < 0) continue;
    const CellBlock& block = *blocks_[block_of_cell_[c]];
    system_->cell_dofs(c, dofs);
    const Eigen::VectorXd skeleton = signed_skeleton_rows(dofs, block.skeleton, u);
    sum += skeleton.dot(block.schur * skeleton);
    if (block.interior.empty()) continue;
    const Eigen::VectorXd interior = interior_rows(dofs, block.interior, u) + block.interior_solve * skeleton;
    sum += (block.interior_factor.matrixU() * interior).squaredNorm();
  }
  if (distribution_.distributed()) sum_over_ranks(distribution_.ranks, &sum, 1);
  return sum;
}

}  // namespace hpcontact::assembly
