// CondensedFactor: per-cell elimination of the interior modes (shared between congruent
// parallelograms), assembly of the skeleton Schur complement S (lower triangle), the skeleton
// solver the distribution names on S.
#include "assembly/condensed_factor.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <map>
#include <numeric>
#include <optional>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "linalg/row_exchange.hpp"
#include "linalg/skeleton_solver_factory.hpp"
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

// The row of a cell's shape s: its dof in global order, or its entry of `cell_rows` (the rows of
// the cell's shapes in a vector held at the rank's local dofs) when given.
int row_of(const std::vector<CellDof>& dofs, const int* cell_rows, int s) {
  return cell_rows ? cell_rows[s] : dofs[s].dof;
}

// Rows of `values` at a cell's interior unknowns `local`.
Eigen::MatrixXd interior_rows(const std::vector<CellDof>& dofs, const std::vector<int>& local,
                              const Eigen::Ref<const Eigen::MatrixXd>& values, const int* cell_rows) {
  Eigen::MatrixXd out(local.size(), values.cols());
  for (std::size_t k = 0; k < local.size(); ++k) out.row(k) = values.row(row_of(dofs, cell_rows, local[k]));
  return out;
}

// Rows of `values` at a cell's skeleton unknowns `local`, times their signs (0 for Dirichlet
// dofs): the coefficients of the cell's unsigned element block.
Eigen::MatrixXd signed_skeleton_rows(const std::vector<CellDof>& dofs, const std::vector<int>& local,
                                     const Eigen::Ref<const Eigen::MatrixXd>& values, const int* cell_rows) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(local.size(), values.cols());
  for (std::size_t s = 0; s < local.size(); ++s)
    if (const auto& dof = dofs[local[s]]; dof.dof >= 0)
      out.row(s) = dof.sign * values.row(row_of(dofs, cell_rows, local[s]));
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
  const int n_cells = system_->n_cells(), n_skeleton = system_->n_skeleton_dofs();
  std::vector<char> contributes(n_cells, 1);
  const bool distributed = distribution.distributed();
  MPI_Comm ranks = distribution.ranks;
  if (distributed) {
    const int rank = rank_and_size(ranks).first;
    HPC_VERIFY(part_of_cell.empty() || static_cast<int>(part_of_cell.size()) == n_cells, "one part per cell");
    const std::vector<int> parts = part_of_cell.empty() ? system_->split_cells_over_ranks(ranks) : part_of_cell;
    for (int c = 0; c < n_cells; ++c) contributes[c] = parts[c] == rank;
  }
  // Distributed, a degenerate cell fails on the rank that owns it: every rank ends the same way.
  // (Serial factors may be built by one rank alone, e.g. a sweep's points: no collective then.)
  std::vector<Eigen::Triplet<double>> lower;
  if (distributed)
    run_on_all_ranks_agreeing([&] { lower = eliminate_interiors(contributes); }, ranks);
  else
    lower = eliminate_interiors(contributes);
  find_local_dofs(std::move(contributes));
  skeleton_solver_ = linalg::make_skeleton_solver(
      n_skeleton, std::move(lower), trailing, distribution, [this] { return local_bddc_hints(); },
      system_->fill_ordering());
  // The skeleton solver's local unknowns are the skeleton dofs of the rank's cells (each has its
  // diagonal entry from S_T): solve_local passes rows between the two without a lookup. (Agreed
  // over the ranks: a rank failing alone would leave the others waiting in a collective call.)
  if (distributed)
    run_on_all_ranks_agreeing(
        [&] {
          const std::vector<int>& unknowns = skeleton_solver_->local_unknowns();
          HPC_VERIFY(std::equal(unknowns.begin(), unknowns.end(), local_dofs().begin(),
                                local_dofs().begin() + n_local_skeleton_),
                     "the skeleton solver's local unknowns differ from the skeleton dofs of the rank's cells");
        },
        ranks);
}

void CondensedFactor::find_local_dofs(std::vector<char> own_cells) {
  if (!distribution_.distributed()) {
    rows_ = LocalRows(size_);
  } else {
    std::vector<CellDof> dofs;
    std::vector<int> local;
    for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
      if (block_of_cell_[c] < 0) continue;
      system_->cell_dofs(c, dofs);
      for (const auto& dof : dofs)
        if (dof.dof >= 0) local.push_back(dof.dof);
    }
    std::sort(local.begin(), local.end());
    local.erase(std::unique(local.begin(), local.end()), local.end());
    rows_ = LocalRows(std::move(own_cells), std::move(local));
    // The local rows of every own cell's shapes, found once (the local solves would search them
    // in every pass over the cells).
    cell_row_start_.assign(block_of_cell_.size(), -1);
    for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
      if (block_of_cell_[c] < 0) continue;
      system_->cell_dofs(c, dofs);
      cell_row_start_[c] = static_cast<long>(cell_rows_.size());
      for (const auto& dof : dofs) cell_rows_.push_back(dof.dof < 0 ? -1 : rows_.row(dof.dof));
    }
  }
  const std::vector<int>& local_dofs = rows_.dofs();
  n_local_skeleton_ = static_cast<int>(
      std::lower_bound(local_dofs.begin(), local_dofs.end(), system_->n_skeleton_dofs()) - local_dofs.begin());
  if (distribution_.distributed()) {
    // Which rank counts each shared dof, through PETSc's layout of the dofs in equal blocks.
    const auto [rank, ranks] = rank_and_size(distribution_.ranks);
    const auto block_start = [&, ranks = ranks](int r) {
      return static_cast<int>(static_cast<long long>(size_) * r / ranks);
    };
    counts_dof_ = linalg::RowExchange(distribution_.ranks, size_, block_start(rank), block_start(rank + 1), local_dofs)
                      .lowest_rank_holds();
  }
}

linalg::BddcHints CondensedFactor::local_bddc_hints() const {
  linalg::BddcHints hints;
  const int k = system_->null_motion_count(), fields = system_->field_count();
  hints.near_null_space = Eigen::MatrixXd::Zero(n_local_skeleton_, k);  // (a rank may own no cell)
  if (fields > 1) hints.fields.assign(n_local_skeleton_, 0), hints.node.assign(n_local_skeleton_, 0);
  std::vector<char> on_boundary(n_local_skeleton_, 0);
  std::vector<CellDof> dofs;
  for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
    if (block_of_cell_[c] < 0) continue;
    system_->cell_dofs(c, dofs);
    const Eigen::MatrixXd motions = k > 0 ? system_->null_motions(c) : Eigen::MatrixXd();
    const std::vector<char> boundary = system_->boundary_unknowns(c);
    const int* rows = cell_rows_.data() + cell_row_start_[c];
    // (a shared vertex gets the same values from each of its cells)
    for (std::size_t s = 0; s < dofs.size(); ++s) {
      if (dofs[s].dof < 0 || dofs[s].interior) continue;
      if (k > 0) hints.near_null_space.row(rows[s]) = dofs[s].sign * motions.row(s);
      if (fields > 1) hints.fields[rows[s]] = static_cast<int>(s) % fields;
      if (boundary[s]) on_boundary[rows[s]] = 1;
    }
    // A shape's components are the cell's unknowns s / fields alike; its node is the lowest kept.
    for (std::size_t first = 0; fields > 1 && first < dofs.size(); first += static_cast<std::size_t>(fields)) {
      int node = -1;
      for (int f = 0; f < fields; ++f)
        if (const CellDof& dof = dofs[first + f]; dof.dof >= 0 && !dof.interior)
          node = node < 0 ? dof.dof : std::min(node, dof.dof);
      for (int f = 0; f < fields; ++f)
        if (const CellDof& dof = dofs[first + f]; dof.dof >= 0 && !dof.interior) hints.node[rows[first + f]] = node;
    }
  }
  for (int i = 0; i < n_local_skeleton_; ++i)
    if (on_boundary[i]) hints.natural_boundary.push_back(i);
  return hints;
}

Eigen::Index CondensedFactor::counted_local_row(int dof) const {
  const auto& dofs = local_dofs();
  const auto found = std::lower_bound(dofs.begin(), dofs.end(), dof);
  if (found == dofs.end() || *found != dof) return -1;
  const auto k = found - dofs.begin();
  return counts_dof_[k] ? k : -1;
}

Eigen::MatrixXd CondensedFactor::multiply_local(const linalg::Coupling& b, const Eigen::MatrixXd& x_local) const {
  HPC_VERIFY(b.cols() == size_ && x_local.rows() == static_cast<Eigen::Index>(local_dofs().size()),
             "B x: sizes do not match");
  if (!distribution_.distributed()) return b * x_local;
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(b.rows(), x_local.cols());
  for (int row = 0; row < b.outerSize(); ++row)
    for (linalg::Coupling::InnerIterator it(b, row); it; ++it)
      if (const Eigen::Index k = counted_local_row(static_cast<int>(it.col())); k >= 0)
        out.row(row) += it.value() * x_local.row(k);
  sum_over_ranks(distribution_.ranks, out.data(), out.size());
  return out;
}

Eigen::MatrixXd CondensedFactor::transpose_share(const linalg::Coupling& b, const Eigen::MatrixXd& y) const {
  HPC_VERIFY(b.cols() == size_ && y.rows() == b.rows(), "Bᵀ y: sizes do not match");
  if (!distribution_.distributed()) return b.transpose() * y;
  Eigen::MatrixXd share = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(local_dofs().size()), y.cols());
  for (int row = 0; row < b.outerSize(); ++row)
    for (linalg::Coupling::InnerIterator it(b, row); it; ++it)
      if (const Eigen::Index k = counted_local_row(static_cast<int>(it.col())); k >= 0)
        share.row(k) += it.value() * y.row(row);
  return share;
}

double CondensedFactor::dot_local(const Eigen::VectorXd& share, const Eigen::VectorXd& x_local) const {
  HPC_VERIFY(share.size() == x_local.size() && share.size() == static_cast<Eigen::Index>(local_dofs().size()),
             "a local vector of the wrong size");
  double sum = share.dot(x_local);
  if (distribution_.distributed()) sum_over_ranks(distribution_.ranks, &sum, 1);
  return sum;
}

std::vector<Eigen::Triplet<double>> CondensedFactor::eliminate_interiors(const std::vector<char>& contributes) {
  const CellSystem& system = *system_;
  const int n_cells = system.n_cells();
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

Eigen::MatrixXd CondensedFactor::interior_corrections(const Eigen::MatrixXd& rhs, bool local,
                                                      Eigen::Index n_skeleton_rows) const {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n_skeleton_rows, rhs.cols());
  std::vector<CellDof> dofs;
  for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
    if (block_of_cell_[c] < 0) continue;
    const CellBlock& block = *blocks_[block_of_cell_[c]];
    if (block.interior.empty()) continue;
    system_->cell_dofs(c, dofs);
    const int* rows = local ? cell_rows_.data() + cell_row_start_[c] : nullptr;
    // (A_ii⁻¹ A_is)ᵀ f_i
    const Eigen::MatrixXd correction =
        block.interior_solve.transpose() * interior_rows(dofs, block.interior, rhs, rows);
    for (std::size_t s = 0; s < block.skeleton.size(); ++s) {
      const auto& dof = dofs[block.skeleton[s]];
      if (dof.dof >= 0) out.row(row_of(dofs, rows, block.skeleton[s])) -= dof.sign * correction.row(s);
    }
  }
  return out;
}

void CondensedFactor::recover_interiors(const Eigen::MatrixXd& rhs, bool local, Eigen::MatrixXd& solution) const {
  std::vector<CellDof> dofs;
  for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
    if (block_of_cell_[c] < 0) continue;
    const CellBlock& block = *blocks_[block_of_cell_[c]];
    if (block.interior.empty()) continue;
    system_->cell_dofs(c, dofs);
    const int* rows = local ? cell_rows_.data() + cell_row_start_[c] : nullptr;
    const Eigen::MatrixXd interior = block.interior_factor.solve(interior_rows(dofs, block.interior, rhs, rows)) -
                                     block.interior_solve * signed_skeleton_rows(dofs, block.skeleton, solution, rows);
    for (std::size_t k = 0; k < block.interior.size(); ++k)
      solution.row(row_of(dofs, rows, block.interior[k])) = interior.row(k);
  }
}

Eigen::MatrixXd CondensedFactor::solve(const Eigen::MatrixXd& rhs) const {
  return solve_around(rhs,
                      [this](const Eigen::MatrixXd& skeleton_rhs) { return skeleton_solver_->solve(skeleton_rhs); });
}

Eigen::MatrixXd CondensedFactor::solve_around(
    const Eigen::MatrixXd& rhs, const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& skeleton_solve) const {
  HPC_VERIFY(rhs.rows() == size_, "right-hand side of the wrong size");
  if (rhs.cols() == 0) return Eigen::MatrixXd(size_, 0);  // (blocks of an empty matrix have no data)
  const int n_skeleton = this->n_skeleton();
  // f_s − A_si A_ii⁻¹ f_i: each rank subtracts its own cells' corrections, summed over the ranks.
  Eigen::MatrixXd condensed = interior_corrections(rhs, false, n_skeleton);
  if (distribution_.distributed()) sum_over_ranks(distribution_.ranks, condensed.data(), condensed.size());
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(size_, rhs.cols());
  out.topRows(n_skeleton) = skeleton_solve(condensed + rhs.topRows(n_skeleton));
  // Each rank recovers its own cells' interior modes (the unknowns after the skeleton, each in one
  // cell); distributed, the other ranks' (zero here) are summed in.
  recover_interiors(rhs, false, out);
  if (distribution_.distributed()) {
    auto interiors = out.bottomRows(size_ - n_skeleton);
    Eigen::MatrixXd summed = interiors;
    sum_over_ranks(distribution_.ranks, summed.data(), summed.size());
    interiors = summed;
  }
  return out;
}

Eigen::MatrixXd CondensedFactor::solve_local(const Eigen::MatrixXd& partial_rhs) const {
  HPC_VERIFY(partial_rhs.rows() == static_cast<Eigen::Index>(local_dofs().size()),
             "right-hand side share of the wrong size");
  if (!distribution_.distributed()) return solve(partial_rhs);
  if (partial_rhs.cols() == 0) return Eigen::MatrixXd(partial_rhs.rows(), 0);
  // A cell's interior modes are its rank's alone, so their rows of the share are the whole
  // right-hand side, and the condensation adds up within the rank: the skeleton solver sums the
  // shares.
  Eigen::MatrixXd out(partial_rhs.rows(), partial_rhs.cols());
  out.topRows(n_local_skeleton_) = skeleton_solver_->solve_local(
      interior_corrections(partial_rhs, true, n_local_skeleton_) + partial_rhs.topRows(n_local_skeleton_));
  recover_interiors(partial_rhs, true, out);
  return out;
}

Eigen::MatrixXd CondensedFactor::solve_skeleton(const Eigen::MatrixXd& rhs) const {
  HPC_VERIFY(rhs.rows() == n_skeleton(), "skeleton right-hand side of the wrong size");
  return skeleton_solver_->solve(rhs);
}

Eigen::VectorXd CondensedFactor::solve(const Eigen::VectorXd& rhs) const { return solve(Eigen::MatrixXd(rhs)).col(0); }

Eigen::MatrixXd CondensedFactor::schur_complement(const linalg::Coupling& b) const {
  HPC_VERIFY(b.cols() == size_, "B A⁻¹ Bᵀ: B has the wrong number of columns");
  const int n_skeleton = this->n_skeleton();
  bool skeleton_only = true;
  for (int row = 0; skeleton_only && row < b.outerSize(); ++row)
    for (linalg::Coupling::InnerIterator it(b, row); it; ++it)
      if (it.col() >= n_skeleton && it.value() != 0.0) skeleton_only = false;
  if (skeleton_only)
    return skeleton_solver_->schur_complement(linalg::squeezed<linalg::Coupling>(b.leftCols(n_skeleton)));
  const Eigen::MatrixXd result = b * solve(Eigen::MatrixXd(b.transpose()));
  return 0.5 * (result + result.transpose());
}

double CondensedFactor::quadratic_form(const Eigen::VectorXd& u) const {
  HPC_VERIFY(u.size() == size_, "quadratic form of a vector of the wrong size");
  return cell_quadratic_forms(u, false);
}

double CondensedFactor::quadratic_form_local(const Eigen::VectorXd& u_local) const {
  HPC_VERIFY(u_local.size() == static_cast<Eigen::Index>(local_dofs().size()),
             "quadratic form of a vector of the wrong size");
  return cell_quadratic_forms(u_local, distribution_.distributed());
}

double CondensedFactor::cell_quadratic_forms(const Eigen::VectorXd& u, bool local) const {
  // uᵀ A u = Σ_T u_sᵀ S_T u_s + ‖Lᵀ (u_i + A_ii⁻¹ A_is u_s)‖², per cell with its signs.
  double sum = 0.0;
  std::vector<CellDof> dofs;
  for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
    if (block_of_cell_[c] < 0) continue;
    const CellBlock& block = *blocks_[block_of_cell_[c]];
    system_->cell_dofs(c, dofs);
    const int* rows = local ? cell_rows_.data() + cell_row_start_[c] : nullptr;
    const Eigen::VectorXd skeleton = signed_skeleton_rows(dofs, block.skeleton, u, rows);
    sum += skeleton.dot(block.schur * skeleton);
    if (block.interior.empty()) continue;
    const Eigen::VectorXd interior = interior_rows(dofs, block.interior, u, rows) + block.interior_solve * skeleton;
    sum += (block.interior_factor.matrixU() * interior).squaredNorm();
  }
  if (distribution_.distributed()) sum_over_ranks(distribution_.ranks, &sum, 1);
  return sum;
}

std::optional<linalg::IterationCounts> CondensedFactor::iterations() const { return skeleton_solver_->iterations(); }

void log_iterations(const CondensedFactor* factor, const std::string& name, OperatorLog* log) {
  if (!factor || !log) return;
  if (const auto counts = factor->iterations())
    log->add_iterations(name, counts->solves, counts->total, counts->largest);
}

}  // namespace hpcontact::assembly
