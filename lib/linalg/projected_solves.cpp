// make_projected_solves: an iterative solver's CG projected onto active rows of C, with
// replicated vectors in and out; each rank works on its owned rows, in node blocks where the
// solver has them.
#include "linalg/projected_solves.hpp"

#include <algorithm>
#include <utility>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_session.hpp"
#include "linalg/projected_cg.hpp"

namespace hpcontact::linalg {
namespace {

// Cᵀ's owned rows (owned × m) moved to the node blocks' rows: through dense chunks of columns,
// since NodeBlocks moves dense columns (a whole dense Cᵀ would be m vectors of the global length).
Eigen::SparseMatrix<double> block_columns(const NodeBlocks& blocks, const Eigen::SparseMatrix<double>& owned_columns) {
  constexpr Eigen::Index kChunk = 32;
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index first = 0; first < owned_columns.cols(); first += kChunk) {
    const Eigen::Index count = std::min(kChunk, owned_columns.cols() - first);
    const Eigen::MatrixXd moved = blocks.to_blocks(Eigen::MatrixXd(owned_columns.middleCols(first, count)));
    for (Eigen::Index j = 0; j < count; ++j)
      for (Eigen::Index i = 0; i < moved.rows(); ++i)
        if (moved(i, j) != 0.0) entries.emplace_back(static_cast<int>(i), static_cast<int>(first + j), moved(i, j));
  }
  Eigen::SparseMatrix<double> out(blocks.owned_block_rows(), owned_columns.cols());
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

// The solver's CG projected onto active rows of C, with replicated vectors in and out: each rank
// works on its owned rows (in node blocks where the solver has them).
class ProjectedSolves : public ConstrainedSolver {
 public:
  ProjectedSolves(MPI_Comm ranks, int n, PetscInt row_begin, PetscInt row_end, const NodeBlocks* blocks,
                  ProjectedConjugateGradients&& iteration, double relative_tolerance)
      : ranks_(ranks),
        n_(n),
        row_begin_(row_begin),
        owned_(row_end - row_begin),
        blocks_(blocks),
        iteration_(std::move(iteration)),
        relative_tolerance_(relative_tolerance) {}

  ConstrainedSolution solve(const Eigen::VectorXd& rhs, const std::vector<int>& active, const Eigen::VectorXd& values,
                            const Eigen::VectorXd& start, double relative_tolerance) override {
    HPC_VERIFY(rhs.size() == n_ && start.size() == n_, "vectors of the wrong size");
    auto owned = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
      Eigen::VectorXd rows = x.segment(row_begin_, owned_);
      return blocks_ ? Eigen::VectorXd(blocks_->to_blocks(rows)) : rows;
    };
    ConstrainedSolution out = iteration_.solve(owned(rhs), active, values, owned(start), relative_tolerance);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n_);
    x.segment(row_begin_, owned_) = blocks_ ? Eigen::VectorXd(blocks_->from_blocks(out.x)) : out.x;
    sum_over_ranks(ranks_, x.data(), static_cast<std::size_t>(n_));  // (each row non-zero on its owner only)
    out.x = std::move(x);
    return out;
  }
  long preconditioner_applications() const override { return iteration_.iterations() + iteration_.applications(); }
  long iterations() const override { return iteration_.iterations(); }
  double relative_tolerance() const override { return relative_tolerance_; }

 private:
  MPI_Comm ranks_;
  int n_;
  PetscInt row_begin_, owned_;
  const NodeBlocks* blocks_;
  ProjectedConjugateGradients iteration_;
  double relative_tolerance_;
};

}  // namespace

std::unique_ptr<ConstrainedSolver> make_projected_solves(MPI_Comm ranks, int n, PetscInt row_begin, PetscInt row_end,
                                                         const NodeBlocks* blocks, Mat a, KSP ksp, const Coupling& c,
                                                         const std::string& name) {
  HPC_VERIFY(c.cols() == n, "constraints with the wrong number of columns");
  const PetscInt owned = row_end - row_begin;
  Eigen::SparseMatrix<double> owned_columns = Eigen::SparseMatrix<double>(c.middleCols(row_begin, owned)).transpose();
  if (blocks) owned_columns = block_columns(*blocks, owned_columns);
  PC pc = nullptr;
  HPC_PETSC_CALL(KSPGetPC(ksp, &pc));
  PetscInt max_iterations = 0;
  PetscReal relative_tolerance = 0.0;
  HPC_PETSC_CALL(KSPGetTolerances(ksp, &relative_tolerance, nullptr, nullptr, &max_iterations));
  ProjectedConjugateGradients iteration(ranks, a, pc, std::move(owned_columns), static_cast<int>(max_iterations), name);
  return std::make_unique<ProjectedSolves>(ranks, n, row_begin, row_end, blocks, std::move(iteration),
                                           relative_tolerance);
}

}  // namespace hpcontact::linalg
