// A library example beside the command line: the paper's Signorini problem (9) on its §7 square
// built from hpcontact's parts, without a scene file — mesh, multiplier mesh, degrees, operators,
// the contact solve, and the inf-sup constant α of the same pairing on the same operators.
//   contact_from_parts [n p pC]      (defaults 8 2 1: T_{C,H} = T_h|Γ_C, h/H = 1)
// Exits 1 if the solve misses its KKT conditions or the pairing is singular.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "contact/contact_problem.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "infsup/infsup_analysis.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "operators/primal_operators.hpp"

using namespace hpcontact;

int main(int argc, char** argv) {
  if (argc != 1 && argc != 4) {
    std::fprintf(stderr, "usage: contact_from_parts [n p pC]\n");
    return 2;
  }
  const int n = argc == 4 ? std::atoi(argv[1]) : 8, p = argc == 4 ? std::atoi(argv[2]) : 2,
            pc = argc == 4 ? std::atoi(argv[3]) : 1;
  try {
    // 1. PETSc and SLEPc, for the eigenproblem of α.
    const PetscSession session({argv[0]});

    // 2. T_h: Ω = (-1, 1)² in n × n squares; Γ_C the bottom edge, Γ_D the top edge and the upper
    //    half of the right edge. T_{C,H}: n uniform segments on Γ_C (its length is 2).
    const mesh::Mesh mesh = mesh::make_paper_square_mesh(n);
    const mesh::BoundaryMesh multiplier_mesh = mesh::BoundaryMesh::uniform(2.0, n);

    // 3. Degrees: p on every cell of T_h, p_C on every segment of T_{C,H}.
    const std::vector<int> cell_degrees(mesh.n_cells(), p), segment_degrees(multiplier_mesh.n_segments(), pc);

    // 4. The operators of S^p(T_h) (K, M, their factorizations, B), built on first use and shared
    //    by the contact solve and α.
    const operators::PrimalOperators primal(mesh, cell_degrees);

    // 5. The contact problem (9): f = -1, the obstacle g = -x².
    contact::ContactSetup problem;
    problem.mesh = &mesh;
    problem.cell_degrees = cell_degrees;
    problem.boundary_mesh = &multiplier_mesh;
    problem.segment_degrees = segment_degrees;
    problem.problem = contact::ContactProblem::signorini;
    problem.f = [](const mesh::Point&) { return -1.0; };
    problem.obstacle = [](const mesh::Point& x) { return -x.x() * x.x(); };
    problem.primal = &primal;
    const contact::ContactSolution solution = contact::solve_contact(problem);
    std::printf("energy = %.15g, %d %s steps, KKT residual %.2e, %d unknowns, %d multipliers\n", solution.energy,
                solution.qp.iterations, solution.qp.method.c_str(), solution.qp.kkt_residual, solution.n_dofs,
                static_cast<int>(solution.lambda.size()));

    // 6. α of the pairing (11) in the interpolation norm of H^{-1/2}(Γ_C), on the same operators.
    infsup::InfSupSetup pairing;
    pairing.mesh = &mesh;
    pairing.cell_degrees = cell_degrees;
    pairing.boundary_mesh = &multiplier_mesh;
    pairing.segment_degrees = segment_degrees;
    pairing.norm = infsup::GramNorm::interpolation;
    pairing.primal = &primal;
    const infsup::InfSupResult alpha = infsup::analyse_infsup(pairing, infsup::EigenBackend::slepc);
    std::printf("alpha = %.10g (error estimate %.1e), Pi = %.4g\n", alpha.alpha, alpha.alpha_error, alpha.pi);

    // 7. What a program would check before trusting λ.
    if (!solution.qp.converged || solution.qp.kkt_residual > 1e-10) return 1;
    if (alpha.singular) {
      std::printf("the pairing is singular: lambda is not unique\n");
      return 1;
    }
  } catch (const InputError& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 3;
  }
  return 0;
}
