// The operators a run built and what each cost: the record behind "a run simulates only the
// effects its scene calls for, and nothing twice". summary.json lists it; tests assert it.
#pragma once

#include <string>
#include <vector>

namespace hpcontact {

struct OperatorRecord {
  std::string name;  ///< e.g. "K", "M", "F", "B", "B^s", "factor(K)", "S", "G", "contact QP"
  long long rows = 0, cols = 0;
  double seconds = 0.0;
};

class OperatorLog {
 public:
  void record(std::string name, long long rows, long long cols, double seconds) {
    records_.push_back({std::move(name), rows, cols, seconds});
  }
  const std::vector<OperatorRecord>& records() const { return records_; }
  /// How often `name` was built (tests: 0 or 1).
  int count(const std::string& name) const {
    int n = 0;
    for (const auto& r : records_) n += r.name == name;
    return n;
  }

 private:
  std::vector<OperatorRecord> records_;
};

}  // namespace hpcontact
