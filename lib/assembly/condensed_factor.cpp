// CondensedFactor: per-cell elimination of the interior modes (shared between congruent
// parallelograms), assembly of the skeleton Schur complement S (lower triangle), CHOLMOD on S.
#include "assembly/condensed_factor.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

#include "assembly/element_matrices.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "mesh/cell_partition.hpp"

namespace hpcontact::assembly {

/// The elimination of one cell's interior modes, with the shapes' signs taken out (a cell's
/// signs are D = diag(sign_s); its element matrix is D A_T D, interior signs are all +1).
struct CondensedFactor::CellBlock {
  std::vector<int> skeleton, interior;          ///< local shape indices
  Eigen::LLT<Eigen::MatrixXd> interior_factor;  ///< A_ii = L Lᵀ
  Eigen::MatrixXd interior_solve;               ///< A_ii⁻¹ A_is, shape (n_interior, n_skeleton_local)
  Eigen::MatrixXd schur;                        ///< S_T = A_ss − A_si A_ii⁻¹ A_is
};

namespace {

bool is_interior(const space::LocalShape& shape) { return shape.i >= 2 && shape.j >= 2; }

// Congruent parallelograms: the same degrees (cell and edges) and the same Jacobian, its entries
// rounded to 1e-12 of the largest: cells of a uniform mesh whose vertex coordinates differ in the
// last bits share their elimination, at a relative change of the element matrix far below 1e-12.
// The rounded entries alone are those of the shape; the size enters the key too (as the log of
// the largest entry, to 1e-11), because the mass matrix scales with the area: similar cells of
// different sizes (the layers of a geometric mesh) must not share a block of K + M.
using ParallelogramKey = std::tuple<int, std::array<int, 4>, std::array<long long, 5>>;

std::array<long long, 5> rounded_jacobian(const Eigen::Matrix2d& jacobian) {
  const double largest = jacobian.cwiseAbs().maxCoeff(), unit = 1e-12 * largest;
  return {std::llround(jacobian(0, 0) / unit), std::llround(jacobian(0, 1) / unit), std::llround(jacobian(1, 0) / unit),
          std::llround(jacobian(1, 1) / unit), std::llround(1e11 * std::log(largest))};
}

// Rows of `values` (global dof order) at a cell's interior shapes `local`.
Eigen::MatrixXd interior_rows(const std::vector<space::LocalShape>& shapes, const std::vector<int>& local,
                              const Eigen::Ref<const Eigen::MatrixXd>& values) {
  Eigen::MatrixXd out(local.size(), values.cols());
  for (std::size_t k = 0; k < local.size(); ++k) out.row(k) = values.row(shapes[local[k]].dof);
  return out;
}

// Rows of `values` at a cell's skeleton shapes `local`, times their signs (0 for Dirichlet dofs):
// the coefficients of the cell's unsigned element block.
Eigen::MatrixXd signed_skeleton_rows(const std::vector<space::LocalShape>& shapes, const std::vector<int>& local,
                                     const Eigen::Ref<const Eigen::MatrixXd>& values) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(local.size(), values.cols());
  for (std::size_t s = 0; s < local.size(); ++s)
    if (const auto& shape = shapes[local[s]]; shape.dof >= 0) out.row(s) = shape.sign * values.row(shape.dof);
  return out;
}

}  // namespace

CondensedFactor::CondensedFactor(const space::H1Space& space, double stiffness_weight, double mass_weight,
                                 const std::vector<int>& trailing, linalg::Distribution distribution)
    : space_(&space), size_(space.n_dofs()), n_trailing_(static_cast<int>(trailing.size())) {
  for (int index : trailing)
    HPC_VERIFY(index >= 0 && index < space.n_skeleton_dofs(), "trailing set outside the skeleton dofs");
  const int n_cells = space.mesh().n_cells(), n_skeleton = space.n_skeleton_dofs();
  std::vector<char> contributes(n_cells, 1);
  if (distribution != linalg::Distribution::serial) {
    const int rank = mpi_rank_and_size().first, ranks = mpi_rank_and_size().second;
    const std::vector<int> part_of_cell = mesh::bisect_cells(space.mesh(), ranks);
    for (int c = 0; c < n_cells; ++c) contributes[c] = part_of_cell[c] == rank;
  }
  auto lower = eliminate_interiors(stiffness_weight, mass_weight, contributes);
  switch (distribution) {
    case linalg::Distribution::serial: {
      Eigen::SparseMatrix<double> schur(n_skeleton, n_skeleton);
      schur.setFromTriplets(lower.begin(), lower.end());
      lower = {};
      serial_ = std::make_unique<linalg::SparseCholesky>(schur, trailing);
      break;
    }
    case linalg::Distribution::substructuring:
      substructured_ = std::make_unique<linalg::SubstructuredCholesky>(n_skeleton, lower, trailing);
      break;
    case linalg::Distribution::mumps:
      mumps_ = std::make_unique<linalg::DistributedCholesky>(n_skeleton, lower);
      break;
  }
}

std::vector<Eigen::Triplet<double>> CondensedFactor::eliminate_interiors(double stiffness_weight, double mass_weight,
                                                                         const std::vector<char>& contributes) {
  const auto& space = *space_;
  const auto& mesh = space.mesh();
  ElementMatrices element(space);
  std::map<ParallelogramKey, int> congruent;
  block_of_cell_.assign(mesh.n_cells(), -1);
  std::vector<Eigen::Triplet<double>> lower;
  Eigen::MatrixXd stiffness, mass;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    const auto& shapes = space.cell_shapes(c);
    Eigen::Matrix2d jacobian;
    std::optional<ParallelogramKey> key;
    if (element.constant_jacobian(c, jacobian)) {
      std::array<int, 4> edge_degrees{};
      for (int e = 0; e < 4; ++e) edge_degrees[e] = space.edge_degree(mesh.cell_edge(c, e));
      key = ParallelogramKey{space.cell_degree(c), edge_degrees, rounded_jacobian(jacobian)};
      if (const auto found = congruent.find(*key); found != congruent.end()) block_of_cell_[c] = found->second;
    }
    if (block_of_cell_[c] < 0) {
      element.compute(c, stiffness_weight != 0.0 ? &stiffness : nullptr, mass_weight != 0.0 ? &mass : nullptr);
      const int n = static_cast<int>(shapes.size());
      Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
      if (stiffness_weight != 0.0) a += stiffness_weight * stiffness;
      if (mass_weight != 0.0) a += mass_weight * mass;
      Eigen::VectorXd sign(n);
      for (int s = 0; s < n; ++s) sign(s) = shapes[s].sign;
      a = sign.asDiagonal() * a * sign.asDiagonal();
      auto block = std::make_unique<CellBlock>();
      for (int s = 0; s < n; ++s) (is_interior(shapes[s]) ? block->interior : block->skeleton).push_back(s);
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
    if (!contributes[c]) continue;
    const CellBlock& block = *blocks_[block_of_cell_[c]];
    // The lower triangle (all CHOLMOD reads); exact zeros (Lobatto orthogonality on
    // parallelograms) stay out of the pattern.
    for (std::size_t t = 0; t < block.skeleton.size(); ++t) {
      const auto& column = shapes[block.skeleton[t]];
      if (column.dof < 0) continue;
      for (std::size_t s = 0; s < block.skeleton.size(); ++s) {
        const auto& row = shapes[block.skeleton[s]];
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
  return substructured_ ? substructured_->solve(rhs) : mumps_->solve(rhs);
}

Eigen::MatrixXd CondensedFactor::condense(const Eigen::MatrixXd& rhs) const {
  Eigen::MatrixXd out = rhs.topRows(n_skeleton());
  for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
    const CellBlock& block = *blocks_[block_of_cell_[c]];
    if (block.interior.empty()) continue;
    const auto& shapes = space_->cell_shapes(c);
    // (A_ii⁻¹ A_is)ᵀ f_i
    const Eigen::MatrixXd correction = block.interior_solve.transpose() * interior_rows(shapes, block.interior, rhs);
    for (std::size_t s = 0; s < block.skeleton.size(); ++s) {
      const auto& shape = shapes[block.skeleton[s]];
      if (shape.dof >= 0) out.row(shape.dof) -= shape.sign * correction.row(s);
    }
  }
  return out;
}

Eigen::MatrixXd CondensedFactor::solve(const Eigen::MatrixXd& rhs) const {
  HPC_VERIFY(rhs.rows() == size_, "right-hand side of the wrong size");
  Eigen::MatrixXd out(size_, rhs.cols());
  out.topRows(n_skeleton()) = skeleton_solve(condense(rhs));
  for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
    const CellBlock& block = *blocks_[block_of_cell_[c]];
    if (block.interior.empty()) continue;
    const auto& shapes = space_->cell_shapes(c);
    const Eigen::MatrixXd interior = block.interior_factor.solve(interior_rows(shapes, block.interior, rhs)) -
                                     block.interior_solve * signed_skeleton_rows(shapes, block.skeleton, out);
    for (std::size_t k = 0; k < block.interior.size(); ++k) out.row(shapes[block.interior[k]].dof) = interior.row(k);
  }
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
    return substructured_ ? substructured_->schur_complement(b_skeleton) : mumps_->schur_complement(b_skeleton);
  }
  const Eigen::MatrixXd result = b * solve(Eigen::MatrixXd(b.transpose()));
  return 0.5 * (result + result.transpose());
}

double CondensedFactor::quadratic_form(const Eigen::VectorXd& u) const {
  HPC_VERIFY(u.size() == size_, "quadratic form of a vector of the wrong size");
  // uᵀ A u = Σ_T u_sᵀ S_T u_s + ‖Lᵀ (u_i + A_ii⁻¹ A_is u_s)‖², per cell with its signs.
  double sum = 0.0;
  for (int c = 0; c < static_cast<int>(block_of_cell_.size()); ++c) {
    const CellBlock& block = *blocks_[block_of_cell_[c]];
    const auto& shapes = space_->cell_shapes(c);
    const Eigen::VectorXd skeleton = signed_skeleton_rows(shapes, block.skeleton, u);
    sum += skeleton.dot(block.schur * skeleton);
    if (block.interior.empty()) continue;
    const Eigen::VectorXd interior = interior_rows(shapes, block.interior, u) + block.interior_solve * skeleton;
    sum += (block.interior_factor.matrixU() * interior).squaredNorm();
  }
  return sum;
}

}  // namespace hpcontact::assembly
