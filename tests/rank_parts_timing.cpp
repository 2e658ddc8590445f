// A measurement, not a test: the first rank's time to cut every rank's part (operators::RankParts:
// the §7 square with n × n cells at p = 4, Γ_D eliminated and kept, bisection into P parts) in one
// process. Usage: rank_parts_timing N P...; one line per P: the seconds and the bytes of all parts.
#include <fmt/format.h>

#include <chrono>
#include <cstdlib>
#include <string>

#include "mesh/cell_partition.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "operators/rank_parts.hpp"

using namespace hpcontact;

int main(int argc, char** argv) {
  if (argc < 3) {
    fmt::print(stderr, "usage: rank_parts_timing N P...\n");
    return 2;
  }
  const mesh::Mesh square = mesh::make_paper_square_mesh(std::stoi(argv[1]));
  operators::WholeNumbering whole;
  const std::vector<int> degrees(square.n_cells(), 4);
  const std::vector<char> none(square.n_cells(), 0);  // numbering only, as on the first rank
  whole.space = std::make_unique<space::H1Space>(square, degrees, space::DirichletDofs::eliminated, none);
  whole.kept = std::make_unique<space::H1Space>(square, degrees, space::DirichletDofs::kept, none);
  const mesh::ContactBoundary contact(square);  // (named: edges() refers into it)
  for (const auto& edge : contact.edges()) whole.contact_cells.push_back(edge.cell);
  for (int a = 2; a < argc; ++a) {
    const int ranks = std::stoi(argv[a]);
    const auto parts = mesh::bisect_cells(square, ranks, std::vector<int>(square.n_cells(), 1));
    const auto start = std::chrono::steady_clock::now();
    const operators::RankParts cutter(square, whole, parts, ranks, nullptr);
    std::size_t bytes = 0;
    for (int rank = 0; rank < ranks; ++rank) bytes += cutter.bytes_for(rank).size();
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    fmt::print("cells {} ranks {} seconds {:.3f} MB {:.1f}\n", square.n_cells(), ranks, seconds.count(), bytes / 1e6);
  }
  return EXIT_SUCCESS;
}
