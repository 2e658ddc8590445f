// SortedIndexMap: positions of a few global indices (an interface, a trailing set, a rank's own
// unknowns) as a sorted vector of pairs, so that the distributed factors hold no lookup array of
// the global length on every rank.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace hpcontact::linalg {

class SortedIndexMap {
 public:
  SortedIndexMap() = default;
  /// (index, position) pairs in any order; an index may appear once.
  explicit SortedIndexMap(std::vector<std::pair<int, int>> entries) : entries_(std::move(entries)) {
    std::sort(entries_.begin(), entries_.end());
    for (std::size_t k = 1; k < entries_.size(); ++k)
      HPC_VERIFY(entries_[k].first != entries_[k - 1].first, "an index is mapped twice");
  }
  /// The position of `index`, or −1 if it is not mapped.
  int find(int index) const {
    const auto it = std::lower_bound(entries_.begin(), entries_.end(), std::pair{index, -1},
                                     [](const auto& a, const auto& b) { return a.first < b.first; });
    return it != entries_.end() && it->first == index ? it->second : -1;
  }
  std::size_t size() const { return entries_.size(); }

 private:
  std::vector<std::pair<int, int>> entries_;
};

}  // namespace hpcontact::linalg
