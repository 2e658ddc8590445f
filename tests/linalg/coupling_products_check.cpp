// Helper of distributed_factor_test, run under mpirun: the products of a distributed
// CondensedFactor with a coupling B (stored by rows, linalg::Coupling) against the serial products
// of the same B. K on a strip with p = 3, B the coupling with M^2 on Γ_C, x and y random and
// the same on every rank. Rank 0 prints the relative differences
//   multiply   B x from each rank's x at its local dofs (multiply_local) against B x,
//   transpose  Σ_r of the ranks' shares of Bᵀ y (transpose_share) against Bᵀ y,
// and `held_dofs_ok 1` if every rank's local dofs lie in the space.
//
//   coupling_products_check SOLVER     (substructuring | mumps | bddc)
#include <fmt/format.h>
#include <mpi.h>

#include <random>
#include <string>

#include "assembly/condensed_factor.hpp"
#include "assembly/coupling.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "mesh/boundary_mesh.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "space/multiplier_space.hpp"

using namespace hpcontact;

namespace {

double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }

int run(const std::string& solver) {
  // A wide strip, so that the split cuts across Γ_C (its bottom) and ranks share trace dofs.
  auto mesh = mesh::make_rectangle_mesh({-4.0, 4.0, -1.0, 1.0}, 24, 4);
  mesh::assign_boundary_part(mesh, mesh::BoundaryPart::contact, [](const mesh::Point& x) { return x.y() < -0.999; });
  mesh::assign_boundary_part(mesh, mesh::BoundaryPart::dirichlet, [](const mesh::Point& x) { return x.y() > 0.999; });
  const space::H1Space space(mesh, 3);
  const mesh::ContactBoundary contact(mesh);
  const auto boundary = mesh::BoundaryMesh::uniform(contact.length(), 5);
  const space::MultiplierSpace multipliers(boundary, 2);
  const linalg::Coupling b = assembly::assemble_coupling(space, contact, multipliers);
  const linalg::Distribution distribution{linalg::parse_distributed_solver(solver, "coupling_products_check", "SOLVER"),
                                          MPI_COMM_WORLD};
  const assembly::CondensedFactor factor(space, 1.0, 0.0, linalg::nonzero_columns(b), distribution);

  std::mt19937 random(11);  // the same x and y on every rank
  std::normal_distribution<double> normal;
  Eigen::VectorXd x(space.n_dofs()), y(multipliers.n_dofs());
  for (auto& value : x) value = normal(random);
  for (auto& value : y) value = normal(random);

  const auto& local = factor.local_dofs();
  bool held_dofs_ok = true;
  Eigen::VectorXd x_local(static_cast<Eigen::Index>(local.size()));
  for (std::size_t k = 0; k < local.size(); ++k) {
    held_dofs_ok = held_dofs_ok && local[k] >= 0 && local[k] < space.n_dofs();
    x_local(static_cast<Eigen::Index>(k)) = held_dofs_ok ? x(local[k]) : 0.0;
  }
  const Eigen::VectorXd product = factor.multiply_local(b, x_local).col(0);
  const Eigen::VectorXd share = factor.transpose_share(b, y).col(0);
  Eigen::VectorXd transpose = Eigen::VectorXd::Zero(space.n_dofs());  // the shares summed (test only)
  for (std::size_t k = 0; k < local.size(); ++k)
    if (held_dofs_ok) transpose(local[k]) += share(static_cast<Eigen::Index>(k));
  MPI_Allreduce(MPI_IN_PLACE, transpose.data(), static_cast<int>(transpose.size()), MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
  int ok = held_dofs_ok ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (mpi_rank_and_size().first != 0) return 0;
  fmt::print("multiply {:.3e}\n", relative_difference(product, b * x));
  fmt::print("transpose {:.3e}\n", relative_difference(transpose, b.transpose() * y));
  fmt::print("held_dofs_ok {}\n", ok);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const PetscSession session({argv[0]});
  try {
    if (argc != 2)
      throw_bad_input("coupling_products_check", "arguments", std::to_string(argc - 1),
                      "substructuring | mumps | bddc");
    return run(argv[1]);
  } catch (const std::exception& error) {
    if (mpi_rank_and_size().first == 0) fmt::print("error: {}\n", error.what());
    return 3;
  }
}
