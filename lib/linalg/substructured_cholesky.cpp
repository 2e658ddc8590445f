// SubstructuredCholesky: the interface found from which ranks contribute to which unknowns, each
// rank's CHOLMOD factor with its interface unknowns last, the dense interface problem assembled
// from the ranks' blocks and factorized over them.
#include "linalg/substructured_cholesky.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <exception>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "linalg/interface_cholesky.hpp"
#include "linalg/schur_complement.hpp"
#include "linalg/shared_unknowns.hpp"
#include "linalg/sorted_index_map.hpp"
#include "linalg/sparse_cholesky.hpp"

namespace hpcontact::linalg {

struct SubstructuredCholesky::Impl {
  int rank = 0;
  std::vector<int> interface;         ///< global index of every interface position (G \ C, then C)
  SortedIndexMap interface_position;  ///< global index → its interface position
  int n_trailing = 0;
  SortedIndexMap trailing_position;                    ///< global index → its row of L_CC
  std::vector<int> interior;                           ///< this rank's interior unknowns (global, ascending)
  std::vector<int> own_interface;                      ///< interface positions this rank touches (ascending)
  std::vector<int> touched;                            ///< the unknowns this rank's entries touch (ascending)
  std::vector<int> interior_slot, own_interface_slot;  ///< where interior / own_interface sit in touched
  std::unique_ptr<SparseCholesky> local;  ///< [interior; own interface] of A_r + D_r (null without interior)
  Eigen::MatrixXd shifted_schur;          ///< S_r + D_r on own_interface
  /// S_G over the ranks (ScaLAPACK between the parts, the trailing block replicated).
  std::optional<InterfaceCholesky> interface_factor;

  int n_local() const { return static_cast<int>(interior.size() + own_interface.size()); }
  /// A solve by parts: the right-hand side's rows at this rank's interior unknowns and the
  /// rank's share of its interface rows (|G| × k, the shares summed over the ranks) in; the
  /// solution's rows there out (the interface rows the same on every rank). Collective on `ranks`.
  struct Parts {
    Eigen::MatrixXd interior, interface;
  };
  Parts solve_parts(MPI_Comm ranks, const Eigen::MatrixXd& interior_rhs, const Eigen::MatrixXd& interface_share) const;
  /// Factorizes this rank's part A_r + D_r (interior unknowns first, own interface positions
  /// last) into `local` and keeps S_r + D_r in `shifted_schur`; returns D_r.
  Eigen::VectorXd factor_own_part(const std::vector<Eigen::Triplet<double>>& lower_entries,
                                  const std::unordered_map<int, int>& local_index);
  /// factor_own_part on every rank of `ranks`, a failure on one agreed on by all, so that none
  /// waits in a collective call. Collective.
  Eigen::VectorXd factor_own_part_on_every_rank(MPI_Comm ranks,
                                                const std::vector<Eigen::Triplet<double>>& lower_entries,
                                                const std::unordered_map<int, int>& local_index);
  /// The interface G (`interface`, `interface_position`, `n_trailing`, `trailing_position`): the
  /// unknowns `shared` between ranks, then the trailing set when it joins them
  /// (trailing_joins_interface; `n_entries`: this rank's entries). Collective.
  void choose_interface(MPI_Comm ranks, const std::vector<int>& shared, const std::vector<int>& trailing_sorted,
                        std::size_t n_entries);
  /// This rank's unknowns among `touched`: `interior` first, then `own_interface`, and where each
  /// sits in `touched`; returns every touched unknown's position in that order.
  std::unordered_map<int, int> number_own_unknowns(const std::vector<int>& touched);
};

Eigen::VectorXd SubstructuredCholesky::Impl::factor_own_part(const std::vector<Eigen::Triplet<double>>& lower_entries,
                                                             const std::unordered_map<int, int>& local_index) {
  Impl& d = *this;
  const int n_interior = static_cast<int>(d.interior.size()), n_own = static_cast<int>(d.own_interface.size());
  const int n_local = n_interior + n_own;
  std::vector<Eigen::Triplet<double>> local_entries;
  local_entries.reserve(lower_entries.size() + n_own);
  Eigen::VectorXd shift = Eigen::VectorXd::Zero(n_own);
  for (const auto& entry : lower_entries) {
    const int row = local_index.at(entry.row()), col = local_index.at(entry.col());
    local_entries.emplace_back(std::max(row, col), std::min(row, col), entry.value());
    if (row == col && row >= n_interior) shift(row - n_interior) += entry.value();
  }
  for (int k = 0; k < n_own; ++k) {
    if (!(shift(k) > 0.0))
      throw NumericalError(
          fmt::format("substructured Cholesky: the diagonal entry of unknown {} is {} (not positive definite)",
                      d.interface[d.own_interface[k]], shift(k)));
    local_entries.emplace_back(n_interior + k, n_interior + k, shift(k));
  }
  Eigen::SparseMatrix<double> local_matrix(n_local, n_local);
  local_matrix.setFromTriplets(local_entries.begin(), local_entries.end());
  local_entries = {};
  if (n_interior == 0) {
    d.shifted_schur = Eigen::MatrixXd(local_matrix).selfadjointView<Eigen::Lower>();
  } else if (n_own == 0) {
    d.local = std::make_unique<SparseCholesky>(local_matrix);
  } else {
    std::vector<int> own(n_own);
    for (int k = 0; k < n_own; ++k) own[k] = n_interior + k;
    d.local = std::make_unique<SparseCholesky>(local_matrix, own);
    Eigen::MatrixXd product = Eigen::MatrixXd::Zero(n_own, n_own);
    product.selfadjointView<Eigen::Lower>().rankUpdate(d.local->trailing_factor());
    std::vector<int> position(n_own);
    for (int k = 0; k < n_own; ++k) position[k] = d.local->trailing_position()[n_interior + k];
    product.triangularView<Eigen::StrictlyUpper>() = product.transpose();
    d.shifted_schur = product(position, position);
  }
  return shift;
}

Eigen::VectorXd SubstructuredCholesky::Impl::factor_own_part_on_every_rank(
    MPI_Comm ranks, const std::vector<Eigen::Triplet<double>>& lower_entries,
    const std::unordered_map<int, int>& local_index) {
  Eigen::VectorXd shift;
  std::exception_ptr failure;
  try {
    shift = factor_own_part(lower_entries, local_index);
  } catch (...) {
    failure = std::current_exception();
  }
  double failed = failure ? 1.0 : 0.0;
  sum_over_ranks(ranks, &failed, 1);
  if (failure) std::rethrow_exception(failure);
  if (failed != 0.0) throw NumericalError("substructured Cholesky: the factorization failed on another rank");
  return shift;
}

namespace {

// The unknowns this rank's entries touch, ascending. (A hash set: the entries are many times the
// unknowns they touch, and sorting them all took 20 % of a factorization's time at 1e6 dofs.)
std::vector<int> touched_unknowns(int n, const std::vector<Eigen::Triplet<double>>& lower_entries) {
  std::unordered_set<int> touched_set;
  for (const auto& entry : lower_entries) {
    HPC_VERIFY(entry.col() >= 0 && entry.row() >= entry.col() && entry.row() < n,
               "substructured Cholesky: entry outside the lower triangle");
    touched_set.insert(entry.row()), touched_set.insert(entry.col());
  }
  std::vector<int> touched(touched_set.begin(), touched_set.end());
  touched_set = {};
  std::sort(touched.begin(), touched.end());
  return touched;
}

// The trailing set ascending, each unknown once.
std::vector<int> sorted_trailing(int n, const std::vector<int>& trailing) {
  std::vector<int> sorted = trailing;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  HPC_VERIFY(sorted.empty() || (sorted.front() >= 0 && sorted.back() < n), "trailing index out of range");
  return sorted;
}

// Whether the trailing set joins the interface: where that is the cheaper way to B A⁻¹ Bᵀ, counted
// per rank and per multiplier (taking as many multipliers as trailing unknowns, the most a trace
// carries). In it: t²/3 + s·t of dense factorization shared by the ranks (t trailing, s shared
// unknowns), and t² to apply its factor, which every rank holds whole. Out of it (each trailing
// unknown interior to the rank that touches it alone): two sweeps through the rank's factor, at
// least twice the entries it holds, and through the interface's factor, 2·s² shared by the ranks
// (schur_complement_by_solves). So the graded trace of the extension norm's references stays out
// (t = 4481, s = 923 at n = 64 on 2 ranks: 2.5e7 against 7.9e6), and the annulus' trace on 2
// ranks joins (t = 1577, s = 747: 3.5e6 against 6.7e6; out of it, S took 20.8 s, not 0.4 s).
// Memory bounds it too: the t² of the trailing block held by every rank must not outweigh the
// rank's share of the matrix entries (`n_entries`, the cells' entries, duplicates counted: a proxy
// for its factor, known before factorizing) beyond 64 MB, or more ranks would gain no memory
// (interface_outweighs_factors). The same answer on every rank. Collective.
bool trailing_joins_interface(MPI_Comm ranks, double t, double s, std::size_t n_entries) {
  const int n_ranks = rank_and_size(ranks).second;
  double entries_per_rank = static_cast<double>(n_entries) / n_ranks;
  sum_over_ranks(ranks, &entries_per_rank, 1);
  const double in_interface = (t * t / 3 + s * t) / n_ranks + t * t;
  const double by_solves = 2 * entries_per_rank + 2 * s * s / n_ranks;
  return n_ranks == 1 || (in_interface <= by_solves && !interface_outweighs_factors(t * t, entries_per_rank));
}

}  // namespace

void SubstructuredCholesky::Impl::choose_interface(MPI_Comm ranks, const std::vector<int>& shared,
                                                   const std::vector<int>& trailing_sorted, std::size_t n_entries) {
  const auto is_trailing = [&](int i) { return std::binary_search(trailing_sorted.begin(), trailing_sorted.end(), i); };
  std::size_t n_shared = 0;
  for (int i : shared) n_shared += !is_trailing(i);
  const bool joins = trailing_joins_interface(ranks, static_cast<double>(trailing_sorted.size()),
                                              static_cast<double>(n_shared), n_entries);
  // Shared unknowns, then the trailing set, each in index order.
  for (int i : shared)
    if (!joins || !is_trailing(i)) interface.push_back(i);
  std::vector<std::pair<int, int>> positions;
  if (joins)
    for (int i : trailing_sorted) positions.emplace_back(i, n_trailing++), interface.push_back(i);
  trailing_position = SortedIndexMap(std::move(positions));
  positions.clear();
  for (int g = 0; g < static_cast<int>(interface.size()); ++g) positions.emplace_back(interface[g], g);
  interface_position = SortedIndexMap(std::move(positions));
}

std::unordered_map<int, int> SubstructuredCholesky::Impl::number_own_unknowns(const std::vector<int>& touched) {
  std::vector<std::pair<int, int>> positions;
  for (int i : touched)
    if (interface_position.find(i) < 0)
      positions.emplace_back(i, static_cast<int>(interior.size())), interior.push_back(i);
  const int n_interior = static_cast<int>(interior.size());
  for (int g = 0; g < static_cast<int>(interface.size()); ++g)
    if (std::binary_search(touched.begin(), touched.end(), interface[g])) {
      positions.emplace_back(interface[g], n_interior + static_cast<int>(own_interface.size()));
      own_interface.push_back(g);
    }
  const auto slot = [&](int i) {
    return static_cast<int>(std::lower_bound(touched.begin(), touched.end(), i) - touched.begin());
  };
  for (int i : interior) interior_slot.push_back(slot(i));
  for (int g : own_interface) own_interface_slot.push_back(slot(interface[g]));
  // A hash map: factor_own_part looks up both ends of every entry.
  std::unordered_map<int, int> local_index(positions.size());
  for (const auto& [index, position] : positions) local_index.emplace(index, position);
  return local_index;
}

SubstructuredCholesky::SubstructuredCholesky(MPI_Comm ranks, int n,
                                             const std::vector<Eigen::Triplet<double>>& lower_entries,
                                             const std::vector<int>& trailing)
    : impl_(std::make_unique<Impl>()), ranks_(ranks), size_(n) {
  Impl& d = *impl_;
  d.rank = rank_and_size(ranks).first;
  // 1. The unknowns this rank's entries touch, and those that more than one rank touches.
  std::vector<int> touched = touched_unknowns(n, lower_entries);
  const std::vector<int> shared = shared_unknowns(ranks, n, touched);
  // 2. The interface G: the shared unknowns, and the trailing set where it joins them.
  d.choose_interface(ranks, shared, sorted_trailing(n, trailing), lower_entries.size());
  // 3. This rank's unknowns: its interior first, then the interface positions it touches.
  const std::unordered_map<int, int> local_index = d.number_own_unknowns(touched);
  // 4. S_r + D_r (D_r: this rank's own diagonal on G): the trailing block of the local factor, or
  // the matrix itself without interior.
  const Eigen::VectorXd shift = d.factor_own_part_on_every_rank(ranks, lower_entries, local_index);
  // 5. S_G = Σ_r (S_r + D_r − D_r), held and factorized over the ranks.
  const int n_own = static_cast<int>(d.own_interface.size());
  for (int k = 0; k < n_own; ++k) d.shifted_schur(k, k) -= shift(k);
  d.interface_factor.emplace(ranks, static_cast<int>(d.interface.size()), d.n_trailing, d.own_interface,
                             d.shifted_schur);
  for (int k = 0; k < n_own; ++k) d.shifted_schur(k, k) += shift(k);
  d.touched = std::move(touched);
  mean_factor_nonzeros_ = d.local ? static_cast<double>(d.local->factor_nonzeros()) : 0.0;
  sum_over_ranks(ranks, &mean_factor_nonzeros_, 1);
  mean_factor_nonzeros_ /= rank_and_size(ranks).second;
}

bool interface_outweighs_factors(double interface_entries, double mean_factor_nonzeros) {
  const double entries = interface_entries;
  constexpr double large = 64e6 / sizeof(double);
  return entries > large && entries > mean_factor_nonzeros;
}

SubstructuredCholesky::~SubstructuredCholesky() = default;
SubstructuredCholesky::SubstructuredCholesky(SubstructuredCholesky&&) noexcept = default;
SubstructuredCholesky& SubstructuredCholesky::operator=(SubstructuredCholesky&&) noexcept = default;

int SubstructuredCholesky::interface_size() const { return static_cast<int>(impl_->interface.size()); }

double SubstructuredCholesky::interface_entries() const { return impl_->interface_factor->stored_entries(); }

SubstructuredCholesky::Impl::Parts SubstructuredCholesky::Impl::solve_parts(
    MPI_Comm ranks, const Eigen::MatrixXd& interior_rhs, const Eigen::MatrixXd& interface_share) const {
  const auto k = interface_share.cols();
  const int n_interior = static_cast<int>(interior.size()), n_own = static_cast<int>(own_interface.size());
  // Condense: g_r = −A_GI A_II⁻¹ f_I = (S_r + D_r) y, where [x; y] solves (A_r + D_r)[x; y] = [f_I;
  // 0].
  Eigen::MatrixXd local_rhs = Eigen::MatrixXd::Zero(n_local(), k), condensed_here;
  local_rhs.topRows(n_interior) = interior_rhs;
  Eigen::MatrixXd condensed = interface_share;
  if (local && n_own > 0) {
    condensed_here = shifted_schur * local->solve(local_rhs).bottomRows(n_own);
    condensed(own_interface, Eigen::all) += condensed_here;
  }
  sum_over_ranks(ranks, condensed.data(), condensed.size());
  Parts out;
  out.interface = interface_factor->solve(condensed);
  // Back-substitute: with the trailing right-hand side (S_r + D_r) u_G − g_r the local solve
  // returns y = u_G, hence x = A_II⁻¹ (f_I − A_IG u_G).
  out.interior = Eigen::MatrixXd::Zero(n_interior, k);
  if (local) {
    if (n_own > 0)
      local_rhs.bottomRows(n_own) = shifted_schur * out.interface(own_interface, Eigen::all) - condensed_here;
    out.interior = local->solve(local_rhs).topRows(n_interior);
  }
  return out;
}

Eigen::MatrixXd SubstructuredCholesky::solve(const Eigen::MatrixXd& rhs) const {
  HPC_VERIFY(rhs.rows() == size_, "right-hand side of the wrong size");
  if (rhs.cols() == 0) return Eigen::MatrixXd(size_, 0);  // (blocks of an empty matrix have no data)
  const Impl& d = *impl_;
  // The interface rows are every rank's: rank 0 passes them as its share.
  const Eigen::MatrixXd interface_share = d.rank == 0 ? Eigen::MatrixXd(rhs(d.interface, Eigen::all))
                                                      : Eigen::MatrixXd::Zero(d.interface.size(), rhs.cols());
  const Impl::Parts parts = d.solve_parts(ranks_, rhs(d.interior, Eigen::all), interface_share);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(size_, rhs.cols());
  out(d.interior, Eigen::all) = parts.interior;
  if (d.rank == 0) out(d.interface, Eigen::all) = parts.interface;
  sum_over_ranks(ranks_, out.data(), out.size());  // every row is set by one rank only
  return out;
}

const std::vector<int>& SubstructuredCholesky::local_unknowns() const { return impl_->touched; }

Eigen::MatrixXd SubstructuredCholesky::solve_local(const Eigen::MatrixXd& partial_rhs) const {
  const Impl& d = *impl_;
  HPC_VERIFY(partial_rhs.rows() == static_cast<Eigen::Index>(d.touched.size()),
             "right-hand side share of the wrong size");
  if (partial_rhs.cols() == 0) return Eigen::MatrixXd(partial_rhs.rows(), 0);
  // An interior unknown is touched by this rank alone: its share is the whole right-hand side.
  Eigen::MatrixXd interface_share = Eigen::MatrixXd::Zero(d.interface.size(), partial_rhs.cols());
  interface_share(d.own_interface, Eigen::all) = partial_rhs(d.own_interface_slot, Eigen::all);
  const Impl::Parts parts = d.solve_parts(ranks_, partial_rhs(d.interior_slot, Eigen::all), interface_share);
  Eigen::MatrixXd out(partial_rhs.rows(), partial_rhs.cols());
  out(d.interior_slot, Eigen::all) = parts.interior;
  out(d.own_interface_slot, Eigen::all) = parts.interface(d.own_interface, Eigen::all);
  return out;
}

Eigen::MatrixXd SubstructuredCholesky::schur_complement(const Coupling& b) const {
  HPC_VERIFY(b.cols() == size_, "B A⁻¹ Bᵀ: B has the wrong number of columns");
  const Impl& d = *impl_;
  if (d.n_trailing == 0) return schur_complement_by_solves(b);
  return schur_complement_through_trailing(
      b, d.interface_factor->trailing_factor(), [&d](int j) { return d.trailing_position.find(j); },
      [this](const Eigen::MatrixXd& rhs) { return solve(rhs); });
}

Eigen::MatrixXd SubstructuredCholesky::schur_complement_by_solves(const Coupling& b) const {
  const Impl& d = *impl_;
  // B's columns at this rank's interior unknowns and at the interface positions (each unknown is
  // one rank's interior or on the interface): no block of the global length.
  std::vector<Eigen::Triplet<double>> interior_entries, interface_entries;
  for (int row = 0; row < b.outerSize(); ++row)
    for (Coupling::InnerIterator it(b, row); it; ++it) {
      const int col = static_cast<int>(it.col());
      const auto interior = std::lower_bound(d.interior.begin(), d.interior.end(), col);
      if (interior != d.interior.end() && *interior == col) {
        interior_entries.emplace_back(it.row(), static_cast<int>(interior - d.interior.begin()), it.value());
        continue;
      }
      if (const int g = d.interface_position.find(col); g >= 0) interface_entries.emplace_back(it.row(), g, it.value());
    }
  using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const auto m = b.rows();
  RowMajor b_interior(m, static_cast<Eigen::Index>(d.interior.size())),
      b_interface(m, static_cast<Eigen::Index>(d.interface.size()));
  b_interior.setFromTriplets(interior_entries.begin(), interior_entries.end());
  b_interface.setFromTriplets(interface_entries.begin(), interface_entries.end());
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(m, m);
  constexpr Eigen::Index block = 64;
  for (Eigen::Index first = 0; first < m; first += block) {
    const auto count = std::min<Eigen::Index>(block, m - first);
    // The interface rows are every rank's: rank 0 passes them as its share.
    const Eigen::MatrixXd interface_share = d.rank == 0
                                                ? Eigen::MatrixXd(b_interface.middleRows(first, count).transpose())
                                                : Eigen::MatrixXd::Zero(d.interface.size(), count);
    const Impl::Parts parts =
        d.solve_parts(ranks_, Eigen::MatrixXd(b_interior.middleRows(first, count).transpose()), interface_share);
    result.middleCols(first, count) = b_interior * parts.interior;
    if (d.rank == 0) result.middleCols(first, count) += b_interface * parts.interface;
  }
  sum_over_ranks(ranks_, result.data(), result.size());
  return 0.5 * (result + result.transpose());
}

}  // namespace hpcontact::linalg
