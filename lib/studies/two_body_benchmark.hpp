// The benchmark's kind "two_body": contact of two elastic blocks on non-matching meshes (the
// slave on n × n/2 cells pressed onto the master on (n + 2) × (n/2 + 1)), its frictionless solve
// against one linear solve of the same two-body system (both bodies factorized and solved once).
#pragma once

#include <functional>

#include "studies/performance_benchmark.hpp"

namespace hpcontact::studies {

/// Adds the rows "linear_A_two_body" (the baseline) and "two_body_frictionless" at level n of
/// `benchmark` (p, p_C, h/H of T_{C,H} on the slave's edges); `base` carries p, p_C and n.
void add_two_body_rows(const PerformanceBenchmark& benchmark, BenchmarkRow base,
                       const std::function<void(BenchmarkRow)>& add);

}  // namespace hpcontact::studies
