// NodeBlocks: each node's first row (its lowest unknown) numbers the node; the ranks owning those
// rows number their nodes contiguously, and one VecScatter moves columns between the unknowns'
// rows and the node blocks' rows.
#include "linalg/node_blocks.hpp"

#include <petscis.h>
#include <petscvec.h>

#include <algorithm>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "core/petsc_handle.hpp"
#include "core/petsc_session.hpp"

namespace hpcontact::linalg {

struct NodeBlocks::Impl {
  std::vector<PetscInt> subdomain;                     ///< the rank's local unknowns (global, ascending)
  std::vector<PetscInt> slot;                          ///< each local unknown's row in the rank's local block matrix
  std::vector<PetscInt> node_blocks;                   ///< the block index of each of the rank's local nodes, ascending
  PetscHandle<Vec, VecDestroy> owned, blocks;          ///< the two layouts
  PetscHandle<VecScatter, VecScatterDestroy> scatter;  ///< owned rows of the unknowns → block rows
};

namespace {

// The owned rows of a vector of the n unknowns given at each local unknown `subdomain[i]` as
// values[i] (ranks sharing an unknown give it the same value), through the MPI Vec `owned`.
std::vector<PetscInt> owned_values(Vec owned, const std::vector<PetscInt>& subdomain, const std::vector<int>& values) {
  for (std::size_t i = 0; i < subdomain.size(); ++i)
    HPC_PETSC_CALL(VecSetValue(owned, subdomain[i], static_cast<PetscScalar>(values[i]), INSERT_VALUES));
  HPC_PETSC_CALL(VecAssemblyBegin(owned));
  HPC_PETSC_CALL(VecAssemblyEnd(owned));
  PetscInt rows = 0;
  HPC_PETSC_CALL(VecGetLocalSize(owned, &rows));
  std::vector<PetscInt> out(rows);
  const PetscScalar* array = nullptr;
  HPC_PETSC_CALL(VecGetArrayRead(owned, &array));
  for (PetscInt r = 0; r < rows; ++r) out[r] = static_cast<PetscInt>(array[r]);
  HPC_PETSC_CALL(VecRestoreArrayRead(owned, &array));
  return out;
}

// The entries of the MPI Vec `from` at the global indices `at`, on this rank.
std::vector<PetscInt> entries_at(Vec from, const std::vector<PetscInt>& at) {
  const auto count = static_cast<PetscInt>(at.size());
  PetscHandle<IS, ISDestroy> indices;
  HPC_PETSC_CALL(ISCreateGeneral(PETSC_COMM_SELF, count, at.data(), PETSC_COPY_VALUES, indices.out()));
  PetscHandle<Vec, VecDestroy> to;
  HPC_PETSC_CALL(VecCreateSeq(PETSC_COMM_SELF, count, to.out()));
  PetscHandle<VecScatter, VecScatterDestroy> scatter;
  HPC_PETSC_CALL(VecScatterCreate(from, indices.get(), to.get(), nullptr, scatter.out()));
  HPC_PETSC_CALL(VecScatterBegin(scatter.get(), from, to.get(), INSERT_VALUES, SCATTER_FORWARD));
  HPC_PETSC_CALL(VecScatterEnd(scatter.get(), from, to.get(), INSERT_VALUES, SCATTER_FORWARD));
  std::vector<PetscInt> out(at.size());
  const PetscScalar* values = nullptr;
  HPC_PETSC_CALL(VecGetArrayRead(to.get(), &values));
  for (std::size_t i = 0; i < at.size(); ++i) out[i] = static_cast<PetscInt>(values[i]);
  HPC_PETSC_CALL(VecRestoreArrayRead(to.get(), &values));
  return out;
}

}  // namespace

NodeBlocks::NodeBlocks(MPI_Comm ranks, int n, PetscInt row_begin, PetscInt row_end,
                       const std::vector<PetscInt>& subdomain, const std::vector<int>& node,
                       const std::vector<int>& field, int components)
    : impl_(std::make_unique<Impl>()), ranks_(ranks), components_(components), owned_rows_(row_end - row_begin) {
  int fits = node.size() == subdomain.size() && field.size() == subdomain.size() ? 1 : 0;
  for (std::size_t i = 0; fits && i < subdomain.size(); ++i)
    fits = node[i] >= 0 && node[i] <= subdomain[i] && field[i] >= 0 && field[i] < components;
  MPI_Allreduce(MPI_IN_PLACE, &fits, 1, MPI_INT, MPI_LAND, ranks);
  HPC_VERIFY(fits, "node blocks: a node or field outside the unknowns (the node is its lowest unknown)");
  impl_->subdomain = subdomain;
  // Each owned row's node and field.
  HPC_PETSC_CALL(VecCreateMPI(ranks, owned_rows_, n, impl_->owned.out()));
  Vec owned = impl_->owned.get();
  const std::vector<PetscInt> owned_node = owned_values(owned, subdomain, node);
  const std::vector<PetscInt> owned_field = owned_values(owned, subdomain, field);
  // The nodes whose first row is the rank's are the rank's, numbered after the lower ranks'.
  PetscInt own_nodes = 0, first_node = 0;
  for (PetscInt r = 0; r < owned_rows_; ++r) own_nodes += owned_node[r] == row_begin + r ? 1 : 0;
  MPI_Exscan(&own_nodes, &first_node, 1, MPIU_INT, MPI_SUM, ranks);
  if (rank_and_size(ranks).first == 0) first_node = 0;  // (MPI_Exscan leaves rank 0's undefined)
  owned_block_rows_ = components * own_nodes;
  {
    PetscScalar* values = nullptr;
    HPC_PETSC_CALL(VecGetArray(owned, &values));
    PetscInt next = first_node;
    for (PetscInt r = 0; r < owned_rows_; ++r) values[r] = owned_node[r] == row_begin + r ? next++ : -1.0;
    HPC_PETSC_CALL(VecRestoreArray(owned, &values));
  }
  // Each local unknown's and owned row's node number, read at the node's first row.
  std::vector<PetscInt> at(node.begin(), node.end());
  at.insert(at.end(), owned_node.begin(), owned_node.end());
  const std::vector<PetscInt> node_number = entries_at(owned, at);
  // The rank's local nodes, and each local unknown's row among them.
  const auto n_local = static_cast<std::ptrdiff_t>(subdomain.size());
  impl_->node_blocks.assign(node_number.begin(), node_number.begin() + n_local);
  std::sort(impl_->node_blocks.begin(), impl_->node_blocks.end());
  impl_->node_blocks.erase(std::unique(impl_->node_blocks.begin(), impl_->node_blocks.end()), impl_->node_blocks.end());
  HPC_VERIFY(impl_->node_blocks.empty() || impl_->node_blocks.front() >= 0, "node blocks: a node without a number");
  impl_->slot.resize(subdomain.size());
  for (std::ptrdiff_t i = 0; i < n_local; ++i) {
    const auto position = std::lower_bound(impl_->node_blocks.begin(), impl_->node_blocks.end(), node_number[i]) -
                          impl_->node_blocks.begin();
    impl_->slot[i] = components * static_cast<PetscInt>(position) + field[i];
  }
  // owned rows → block rows.
  std::vector<PetscInt> block_row(owned_rows_);
  for (PetscInt r = 0; r < owned_rows_; ++r) block_row[r] = components * node_number[n_local + r] + owned_field[r];
  HPC_PETSC_CALL(VecCreateMPI(ranks, owned_block_rows_, PETSC_DETERMINE, impl_->blocks.out()));
  PetscHandle<IS, ISDestroy> from, to;
  HPC_PETSC_CALL(ISCreateStride(PETSC_COMM_SELF, owned_rows_, row_begin, 1, from.out()));
  HPC_PETSC_CALL(ISCreateGeneral(PETSC_COMM_SELF, owned_rows_, block_row.data(), PETSC_COPY_VALUES, to.out()));
  HPC_PETSC_CALL(VecScatterCreate(owned, from.get(), impl_->blocks.get(), to.get(), impl_->scatter.out()));
}

NodeBlocks::~NodeBlocks() = default;
NodeBlocks::NodeBlocks(NodeBlocks&&) noexcept = default;
NodeBlocks& NodeBlocks::operator=(NodeBlocks&&) noexcept = default;

void NodeBlocks::assemble(const std::vector<Eigen::Triplet<double>>& lower_entries, Mat* out) const {
  const auto& subdomain = impl_->subdomain;
  auto slot_of = [&](PetscInt g) {
    return impl_->slot[std::lower_bound(subdomain.begin(), subdomain.end(), g) - subdomain.begin()];
  };
  const auto n_slots = components_ * static_cast<PetscInt>(impl_->node_blocks.size());
  std::vector<PetscInt> rows, cols;
  std::vector<PetscScalar> values;
  std::vector<double> diagonal(n_slots, 0.0);
  std::vector<char> taken(n_slots, 0);
  for (PetscInt s : impl_->slot) taken[s] = 1;
  for (const auto& entry : lower_entries) {
    const PetscInt r = slot_of(entry.row()), c = slot_of(entry.col());
    rows.push_back(r), cols.push_back(c), values.push_back(entry.value());
    if (r != c) rows.push_back(c), cols.push_back(r), values.push_back(entry.value());
    if (r == c) diagonal[r] += entry.value();
  }
  // A removed component's row: its node's mean diagonal, so that the block's scale (what GAMG's
  // strength of connection compares) is the node's own.
  for (PetscInt first = 0; first < n_slots; first += components_) {
    double sum = 0.0;
    int present = 0;
    for (int f = 0; f < components_; ++f)
      if (taken[first + f]) sum += diagonal[first + f], ++present;
    const double scale = present > 0 && sum > 0.0 ? sum / present : 1.0;
    for (int f = 0; f < components_; ++f)
      if (!taken[first + f]) rows.push_back(first + f), cols.push_back(first + f), values.push_back(scale);
  }
  PetscHandle<ISLocalToGlobalMapping, ISLocalToGlobalMappingDestroy> map;
  HPC_PETSC_CALL(ISLocalToGlobalMappingCreate(ranks_, components_, static_cast<PetscInt>(impl_->node_blocks.size()),
                                              impl_->node_blocks.data(), PETSC_COPY_VALUES, map.out()));
  HPC_PETSC_CALL(MatCreateIS(ranks_, components_, owned_block_rows_, owned_block_rows_, PETSC_DETERMINE,
                             PETSC_DETERMINE, map.get(), map.get(), out));
  Mat local = nullptr;
  HPC_PETSC_CALL(MatISGetLocalMat(*out, &local));
  HPC_PETSC_CALL(MatSetType(local, MATSEQAIJ));
  HPC_PETSC_CALL(MatSetPreallocationCOO(local, static_cast<PetscCount>(rows.size()), rows.data(), cols.data()));
  HPC_PETSC_CALL(MatSetValuesCOO(local, values.data(), ADD_VALUES));
  HPC_PETSC_CALL(MatISRestoreLocalMat(*out, &local));
  HPC_PETSC_CALL(MatAssemblyBegin(*out, MAT_FINAL_ASSEMBLY));
  HPC_PETSC_CALL(MatAssemblyEnd(*out, MAT_FINAL_ASSEMBLY));
  HPC_PETSC_CALL(MatConvert(*out, MATAIJ, MAT_INPLACE_MATRIX, out));
}

namespace {

// Copies column `k` of `matrix` into the Vec `v` (whose local length is matrix.rows()), or back.
void column_into(const Eigen::MatrixXd& matrix, Eigen::Index k, Vec v) {
  PetscScalar* array = nullptr;
  HPC_PETSC_CALL(VecGetArray(v, &array));
  std::copy(matrix.col(k).data(), matrix.col(k).data() + matrix.rows(), array);
  HPC_PETSC_CALL(VecRestoreArray(v, &array));
}
void column_from(Vec v, Eigen::MatrixXd& matrix, Eigen::Index k) {
  const PetscScalar* array = nullptr;
  HPC_PETSC_CALL(VecGetArrayRead(v, &array));
  std::copy(array, array + matrix.rows(), matrix.col(k).data());
  HPC_PETSC_CALL(VecRestoreArrayRead(v, &array));
}

}  // namespace

Eigen::MatrixXd NodeBlocks::to_blocks(const Eigen::MatrixXd& owned) const {
  HPC_VERIFY(owned.rows() == owned_rows_, "node blocks: columns of the wrong length");
  Eigen::MatrixXd out(owned_block_rows_, owned.cols());
  for (Eigen::Index k = 0; k < owned.cols(); ++k) {
    column_into(owned, k, impl_->owned.get());
    HPC_PETSC_CALL(VecSet(impl_->blocks.get(), 0.0));
    HPC_PETSC_CALL(
        VecScatterBegin(impl_->scatter.get(), impl_->owned.get(), impl_->blocks.get(), INSERT_VALUES, SCATTER_FORWARD));
    HPC_PETSC_CALL(
        VecScatterEnd(impl_->scatter.get(), impl_->owned.get(), impl_->blocks.get(), INSERT_VALUES, SCATTER_FORWARD));
    column_from(impl_->blocks.get(), out, k);
  }
  return out;
}

Eigen::MatrixXd NodeBlocks::from_blocks(const Eigen::MatrixXd& owned_blocks) const {
  HPC_VERIFY(owned_blocks.rows() == owned_block_rows_, "node blocks: columns of the wrong length");
  Eigen::MatrixXd out(owned_rows_, owned_blocks.cols());
  for (Eigen::Index k = 0; k < owned_blocks.cols(); ++k) {
    column_into(owned_blocks, k, impl_->blocks.get());
    HPC_PETSC_CALL(
        VecScatterBegin(impl_->scatter.get(), impl_->blocks.get(), impl_->owned.get(), INSERT_VALUES, SCATTER_REVERSE));
    HPC_PETSC_CALL(
        VecScatterEnd(impl_->scatter.get(), impl_->blocks.get(), impl_->owned.get(), INSERT_VALUES, SCATTER_REVERSE));
    column_from(impl_->owned.get(), out, k);
  }
  return out;
}

}  // namespace hpcontact::linalg
