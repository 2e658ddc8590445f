// LocalRows: where a vector lives on one rank. Serial, every cell, in the global numbering. On a
// rank of a distributed run, its own cells, one row per dof of those cells: loads are assembled
// into it as the rank's share (the ranks' shares sum to the load), solutions come back in it
// (equal where ranks share a dof), and the outputs read the rank's cells from it — no rank holds
// a vector of the global length. Copies share the (immutable) index arrays.
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include "core/error.hpp"

namespace hpcontact::assembly {

class LocalRows {
 public:
  /// Every cell, rows in the global numbering (dofs() not listed).
  LocalRows() = default;
  /// Every cell, rows in the global numbering, dofs() listing all `n_dofs` of them.
  explicit LocalRows(int n_dofs) : dofs_(std::make_shared<std::vector<int>>(n_dofs)) {
    for (int d = 0; d < n_dofs; ++d) (*dofs_)[d] = d;
  }
  /// The cells c with own_cells[c], their dofs at rows `dofs` (ascending, holding every dof of
  /// those cells).
  LocalRows(std::vector<char> own_cells, std::vector<int> dofs)
      : cells_(std::make_shared<const std::vector<char>>(std::move(own_cells))),
        dofs_(std::make_shared<std::vector<int>>(std::move(dofs))) {}

  /// Whether rows are the global numbering (every cell held).
  bool global() const { return !cells_; }
  bool holds(int cell) const { return !cells_ || (*cells_)[cell]; }
  /// The length of a vector in this layout, for a space of `n_dofs` unknowns.
  int size(int n_dofs) const { return cells_ ? static_cast<int>(dofs_->size()) : n_dofs; }
  /// The row of unknown `dof` (which a cell held here must have).
  int row(int dof) const {
    if (!cells_) return dof;
    const auto it = std::lower_bound(dofs_->begin(), dofs_->end(), dof);
    HPC_VERIFY(it != dofs_->end() && *it == dof, "a row outside the rank's local dofs");
    return static_cast<int>(it - dofs_->begin());
  }
  /// The unknown of each row (ascending).
  const std::vector<int>& dofs() const {
    static const std::vector<int> none;
    return dofs_ ? *dofs_ : none;
  }

 private:
  std::shared_ptr<const std::vector<char>> cells_;
  std::shared_ptr<std::vector<int>> dofs_;
};

}  // namespace hpcontact::assembly
