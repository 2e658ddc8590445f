// What each level of a stability sweep is (cells, Γ_C's edges, segments and degrees per ratio),
// found when the sweep is read, before anything is computed: resuming and scheduling need it.
// Under mpirun one rank builds the levels' meshes and sends the facts (Gmsh runs once, not once
// per rank, and no other rank holds a level's whole mesh while reading).
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

#include "studies/stability_sweep.hpp"

namespace hpcontact::studies {

/// The facts of every level of `sweep` (its levels, ratios and problems read), checking each
/// level's meshes and data. Collective on `ranks`: the first builds, every rank returns the facts.
/// @throws InputError naming `base` (the sweep's scene) and the level, on every rank.
std::vector<StabilitySweep::LevelFacts> sweep_level_facts(const StabilitySweep& sweep, const std::string& base,
                                                          MPI_Comm ranks);

}  // namespace hpcontact::studies
