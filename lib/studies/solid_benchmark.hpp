// The benchmark's kind "three_d": frictionless contact of an elastic cube on n × n × n hexahedra
// against a paraboloid obstacle, on both paths of S (dense from the factor's trailing block, and by
// products), against one linear solve of the same elasticity matrix.
#pragma once

#include <functional>

#include "studies/performance_benchmark.hpp"

namespace hpcontact::studies {

/// Adds the rows "linear_A_3d" (the baseline: factorization and one solve of A), then
/// "three_d_frictionless_dense" and "three_d_frictionless_products" at level n of `benchmark`
/// (p, p_C, h/H of T_{C,H} on Γ_C); `base` carries p, p_C and n.
void add_solid_rows(const PerformanceBenchmark& benchmark, BenchmarkRow base,
                    const std::function<void(BenchmarkRow)>& add);

}  // namespace hpcontact::studies
