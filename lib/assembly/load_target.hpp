// LoadTarget: where a load vector is assembled — over every cell in the global numbering, or, on
// a rank of a distributed run, as the rank's share: its own cells into the rows of its local dofs
// (the ranks' shares sum to the load, and no rank holds a vector of the global length).
#pragma once

#include <algorithm>
#include <vector>

#include "core/error.hpp"

namespace hpcontact::assembly {

class LoadTarget {
 public:
  /// Every cell, rows in the global numbering.
  LoadTarget() = default;
  /// The cells c with own_cells[c], into rows at `local_dofs` (ascending, holding every dof of
  /// those cells). Both must outlive the target.
  LoadTarget(const std::vector<char>& own_cells, const std::vector<int>& local_dofs)
      : own_cells_(&own_cells), local_dofs_(&local_dofs) {}

  bool assembles(int cell) const { return !own_cells_ || (*own_cells_)[cell]; }
  /// The length of the assembled vector, for a space of `n_dofs` unknowns.
  int size(int n_dofs) const { return local_dofs_ ? static_cast<int>(local_dofs_->size()) : n_dofs; }
  /// The row of unknown `dof` (which a cell this target assembles must hold).
  int row(int dof) const {
    if (!local_dofs_) return dof;
    const auto it = std::lower_bound(local_dofs_->begin(), local_dofs_->end(), dof);
    HPC_VERIFY(it != local_dofs_->end() && *it == dof, "a load row outside the rank's local dofs");
    return static_cast<int>(it - local_dofs_->begin());
  }

 private:
  const std::vector<char>* own_cells_ = nullptr;
  const std::vector<int>* local_dofs_ = nullptr;
};

}  // namespace hpcontact::assembly
