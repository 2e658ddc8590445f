// The benchmark's kinds "three_d": frictionless contact of an elastic cube on n × n × n hexahedra
// against a paraboloid obstacle, on both paths of S (dense from the factor's trailing block, and by
// products), against one linear solve of the same elasticity matrix; and "three_d_alpha": α of a
// scalar slab's pairing on both paths against one linear solve with A_G; "three_d_scene": an
// elastic 3-D scene file's contact solve by products against one linear solve of its K.
#pragma once

#include <functional>

#include "studies/performance_benchmark.hpp"

namespace hpcontact::studies {

/// Adds the rows "linear_A_3d" (the baseline: factorization and one solve of A), then
/// "three_d_frictionless_dense" and "three_d_frictionless_products" at level n of `benchmark`
/// (p, p_C, h/H of T_{C,H} on Γ_C); `base` carries p, p_C and n.
void add_solid_rows(const PerformanceBenchmark& benchmark, BenchmarkRow base,
                    const std::function<void(BenchmarkRow)>& add);

/// Kind "three_d_scene": the elastic 3-D scene `benchmark.scene` (its T_{C,H} and first effect,
/// frictionless, Tresca or Coulomb: products summed over the fixed point) at benchmark.p and
/// benchmark.pC. Rows "linear_A_3d_scene" (the baseline:
/// factorization of K with a free ordering and one solve) and "three_d_scene_products" (the contact
/// solve with S by products, factorization included, assembly excluded), n = 0.
/// @throws InputError for a scene that is not 3-D and elastic, naming benchmark.scene.
void add_solid_scene_rows(const PerformanceBenchmark& benchmark, const std::function<void(BenchmarkRow)>& add);

/// Kind "three_d_scene_saddle_point": the scene's frictionless contact on the iterative K (GAMG on
/// one process), solve.trace_operator = "saddle_point", against one GAMG-CG solve of the same K
/// whose load is the contact's (F − B_nᵀ P: the same u, so the same work for the iteration), both
/// with the GAMG set-up. Rows "linear_A_3d_scene_gamg" and "three_d_scene_saddle_point", each with
/// its own peak memory and its CG iterations as `products`.
/// @throws InputError for a scene that is not 3-D, elastic and frictionless; NumericalError if the
/// two u differ by more than 1e-6 of the largest.
void add_solid_saddle_point_rows(const PerformanceBenchmark& benchmark, const std::function<void(BenchmarkRow)>& add);

/// Multipliers up to which kind "three_d_alpha" also runs the dense path.
inline constexpr int kDenseAlphaUpTo = 2500;

/// Kind "three_d_alpha": the scalar slab (−1, 1)² × (−1, −1 + 2 n_z/n) on n × n × n_z cubes
/// (n_z = max(2, n/16)), Γ_C the bottom, Γ_D the top, T_{C,H} by `benchmark`'s ratio and p_C. Rows
/// "linear_AG_3d" (the baseline: factorization of A_G = K + M and one solve), "alpha_3d_products"
/// (α by products, the factorization included) and, up to kDenseAlphaUpTo multipliers,
/// "alpha_3d_dense". @throws NumericalError if the two α differ by more than 1e-7 relative.
void add_solid_alpha_rows(const PerformanceBenchmark& benchmark, BenchmarkRow base,
                          const std::function<void(BenchmarkRow)>& add);

}  // namespace hpcontact::studies
