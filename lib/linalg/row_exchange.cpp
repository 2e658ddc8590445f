// RowExchange: one VecScatter from the owned rows (an MPI Vec) to the local unknowns (a
// sequential Vec); forward with INSERT reads values, reverse with ADD sums the ranks' shares.
#include "linalg/row_exchange.hpp"

#include <petscis.h>
#include <petscvec.h>

#include <algorithm>
#include <limits>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_handle.hpp"
#include "core/petsc_session.hpp"

namespace hpcontact::linalg {

struct RowExchange::Impl {
  PetscHandle<Vec, VecDestroy> owned, local;  ///< layouts only: columns are placed in by VecPlaceArray
  PetscHandle<VecScatter, VecScatterDestroy> scatter;
};

RowExchange::RowExchange(MPI_Comm ranks, int n, int row_begin, int row_end, std::vector<int> local)
    : impl_(std::make_unique<Impl>()), local_(std::move(local)), row_begin_(row_begin), row_end_(row_end) {
  HPC_VERIFY(0 <= row_begin && row_begin <= row_end && row_end <= n, "row exchange: owned rows outside the unknowns");
  HPC_VERIFY(std::is_sorted(local_.begin(), local_.end()) &&
                 std::adjacent_find(local_.begin(), local_.end()) == local_.end() &&
                 (local_.empty() || (local_.front() >= 0 && local_.back() < n)),
             "row exchange: local unknowns not ascending, repeated or outside the unknowns");
  MPI_Comm_rank(ranks, &rank_);
  const auto n_local = static_cast<PetscInt>(local_.size());
  HPC_PETSC_CALL(VecCreateMPIWithArray(ranks, 1, row_end - row_begin, n, nullptr, impl_->owned.out()));
  HPC_PETSC_CALL(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n_local, nullptr, impl_->local.out()));
  const std::vector<PetscInt> global(local_.begin(), local_.end());
  PetscHandle<IS, ISDestroy> from, to;
  HPC_PETSC_CALL(ISCreateGeneral(PETSC_COMM_SELF, n_local, global.data(), PETSC_COPY_VALUES, from.out()));
  HPC_PETSC_CALL(ISCreateStride(PETSC_COMM_SELF, n_local, 0, 1, to.out()));
  HPC_PETSC_CALL(VecScatterCreate(impl_->owned.get(), from.get(), impl_->local.get(), to.get(), impl_->scatter.out()));
}

RowExchange::~RowExchange() = default;
RowExchange::RowExchange(RowExchange&&) noexcept = default;
RowExchange& RowExchange::operator=(RowExchange&&) noexcept = default;

namespace {

// An array placed into a layout Vec for one scatter, taken out again also when the scatter throws
// (a Vec left holding a placed array refuses the next VecPlaceArray).
class PlacedArray {
 public:
  PlacedArray(Vec vector, double* array) : vector_(vector) { HPC_PETSC_CALL(VecPlaceArray(vector, array)); }
  ~PlacedArray() { VecResetArray(vector_); }
  PlacedArray(const PlacedArray&) = delete;
  PlacedArray& operator=(const PlacedArray&) = delete;

 private:
  Vec vector_;
};

}  // namespace

void RowExchange::scatter(double* owned, double* local, InsertMode mode, ScatterMode direction) const {
  const PlacedArray owned_column(impl_->owned.get(), owned), local_column(impl_->local.get(), local);
  Vec from = impl_->owned.get(), to = impl_->local.get();
  if (direction == SCATTER_REVERSE) std::swap(from, to);
  HPC_PETSC_CALL(VecScatterBegin(impl_->scatter.get(), from, to, mode, direction));
  HPC_PETSC_CALL(VecScatterEnd(impl_->scatter.get(), from, to, mode, direction));
}

Eigen::MatrixXd RowExchange::sum_to_owned(const Eigen::MatrixXd& partial) const {
  HPC_VERIFY(partial.rows() == static_cast<Eigen::Index>(local_.size()), "row exchange: wrong number of local rows");
  // Every rank loops over the same column count (the caller's k is the same on every rank).
  Eigen::MatrixXd owned = Eigen::MatrixXd::Zero(owned_rows(), partial.cols());
  Eigen::MatrixXd source = partial;  // VecPlaceArray takes a non-const array
  for (Eigen::Index j = 0; j < partial.cols(); ++j)
    scatter(owned.col(j).data(), source.col(j).data(), ADD_VALUES, SCATTER_REVERSE);
  return owned;
}

Eigen::MatrixXd RowExchange::consistent_to_owned(const Eigen::MatrixXd& local) const {
  HPC_VERIFY(local.rows() == static_cast<Eigen::Index>(local_.size()), "row exchange: wrong number of local rows");
  Eigen::MatrixXd owned = Eigen::MatrixXd::Zero(owned_rows(), local.cols());
  Eigen::MatrixXd source = local;
  for (Eigen::Index j = 0; j < local.cols(); ++j)  // (any holder's value: they are equal)
    scatter(owned.col(j).data(), source.col(j).data(), INSERT_VALUES, SCATTER_REVERSE);
  return owned;
}

Eigen::MatrixXd RowExchange::owned_to_local(const Eigen::MatrixXd& owned) const {
  HPC_VERIFY(owned.rows() == owned_rows(), "row exchange: wrong number of owned rows");
  Eigen::MatrixXd local(static_cast<Eigen::Index>(local_.size()), owned.cols());
  Eigen::MatrixXd source = owned;
  for (Eigen::Index j = 0; j < owned.cols(); ++j)
    scatter(source.col(j).data(), local.col(j).data(), INSERT_VALUES, SCATTER_FORWARD);
  return local;
}

std::vector<char> RowExchange::lowest_rank_holds() const {
  // The largest −rank over the holders of each owned row is −(the lowest holder).
  Eigen::VectorXd minus_rank = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(local_.size()), -rank_);
  Eigen::VectorXd owned = Eigen::VectorXd::Constant(owned_rows(), -std::numeric_limits<double>::infinity());
  scatter(owned.data(), minus_rank.data(), MAX_VALUES, SCATTER_REVERSE);
  const Eigen::MatrixXd lowest = owned_to_local(owned);
  std::vector<char> holds(local_.size());
  for (std::size_t k = 0; k < local_.size(); ++k) holds[k] = lowest(static_cast<Eigen::Index>(k), 0) == -rank_;
  return holds;
}

Eigen::MatrixXd solve_replicated(MPI_Comm ranks, int row_begin, int row_end, const Eigen::MatrixXd& rhs,
                                 const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& solve_owned) {
  const auto n = rhs.rows();
  if (rhs.cols() == 0) return Eigen::MatrixXd(n, 0);  // (blocks of an empty matrix have no data)
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, rhs.cols());
  out.middleRows(row_begin, row_end - row_begin) = solve_owned(rhs.middleRows(row_begin, row_end - row_begin));
  sum_over_ranks(ranks, out.data(), out.size());  // each row is non-zero on its owner only
  return out;
}

}  // namespace hpcontact::linalg
