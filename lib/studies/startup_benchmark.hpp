// Whole-process start-up cost: a tiny `solve` against `--version` of the same executable, both as
// separate processes in the same run, so that what a user waits for before any numerics (loading
// libraries, starting MPI) is measured like every other cost: as a ratio to a baseline.
#pragma once

#include <string>

#include "studies/performance_benchmark.hpp"

namespace hpcontact::studies {

/// Kind "startup": the median wall time of `executable solve SCENE --effects friction_s` on the
/// built-in §7 scene (8 × 8 cells, p = 1; its outputs into a temporary folder) over `runs` runs,
/// against the median of `executable --version`, one process at a time.
/// @throws IoError if a process cannot be started or fails.
BenchmarkRow startup_row(const std::string& executable, int runs = 7);

}  // namespace hpcontact::studies
