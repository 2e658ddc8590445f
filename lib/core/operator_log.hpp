// The operators a run built and what each cost: the record behind "a run simulates only the
// effects its scene calls for, and nothing twice". summary.json lists it; tests assert it.
#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace hpcontact {

struct OperatorRecord {
  std::string name;  ///< e.g. "K", "M", "F", "B", "B^s", "factor(K)", "S", "G", "contact QP"
  long long rows = 0, cols = 0;
  double seconds = 0.0;
  /// A factorization solved by iterations (BDDC), once released: its solves, their iterations in
  /// all and the most in one solve; 0 otherwise.
  long long solves = 0, iterations = 0;
  int most_iterations = 0;
};

class OperatorLog {
 public:
  void record(std::string name, long long rows, long long cols, double seconds) {
    records_.push_back({std::move(name), rows, cols, seconds});
  }
  /// A record made elsewhere (e.g. another log's, renamed).
  void append(OperatorRecord record) { records_.push_back(std::move(record)); }
  /// Adds iteration counts to the latest record of `name` (none: nothing).
  void add_iterations(const std::string& name, long long solves, long long iterations, int most_iterations) {
    for (auto r = records_.rbegin(); r != records_.rend(); ++r)
      if (r->name == name) {
        r->solves += solves, r->iterations += iterations;
        r->most_iterations = std::max(r->most_iterations, most_iterations);
        return;
      }
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
