// A discretization fitted to the free boundary of a contact problem: the scene's mesh is graded
// (local geometric layers, mesh::grade_towards_vertices) towards the ends of the discrete contact
// set or stick zone, located on the previous solution, until they stop moving. With the
// singularities at vertices of geometric meshes, hp refinement converges exponentially; this is
// how the work–precision study computes references accurate beyond 1e-9.
#pragma once

#include <mpi.h>

#include <vector>

#include "driver/scene_discretization.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"

namespace hpcontact::driver {

struct FreeBoundaryFit {
  scene::Scene scene;               ///< the input scene with the fitted points added to domain.grading_points
  std::vector<mesh::Point> points;  ///< the fitted free-boundary points, in order along Γ_C
  double moved = 0.0;               ///< arc length the points moved in the last iteration
  int solves = 0;                   ///< rounds: each solves every problem once
};

/// Solves each of `problems` on the scene, adds the located free-boundary points of all of them
/// (contact::locate_free_boundary; points within one coarse cell of each other are one, at their mean)
/// to its grading points (except those within the longest edge of a grading point the scene
/// gives), and repeats until their number is unchanged and none moves by more
/// than `tolerance` · |Γ_C| (points closer than that count as one). The default 1e-6 is about
/// what the discrete multiplier can resolve and, the singularity being d^{3/2}, moves the energy
/// by far less than 1e-12. @throws NumericalError if that takes more than `max_solves` solves;
/// InputError if a point cannot be a grading point of the scene's mesh (too close to another).
FreeBoundaryFit fit_free_boundary(const scene::Scene& scene, const std::vector<contact::ContactProblem>& problems,
                                  double tolerance = 1e-6, int max_solves = 12);

/// The same fit under mpirun: the first rank of `ranks` fits (serially: the fit's meshes are
/// small) and sends the points; every rank returns the same fit, or raises the same error.
/// Collective on `ranks`.
FreeBoundaryFit fit_free_boundary_once(const scene::Scene& scene, const std::vector<contact::ContactProblem>& problems,
                                       MPI_Comm ranks);

}  // namespace hpcontact::driver
