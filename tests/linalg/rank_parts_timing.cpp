// A measurement, not a test: the first rank's time to cut every rank's part (operators::RankParts:
// the §7 square with n × n cells at p = 4, Γ_D eliminated and kept, bisection into P parts) in one
// process. Usage: rank_parts_timing N P...; one line per P: the seconds and the bytes of all parts.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/cell_partition.hpp"
#include "mesh/rectangle_mesh.hpp"
#include "operators/rank_parts.hpp"

using namespace hpcontact;

namespace {

void time_cutting(int n, const std::vector<int>& rank_counts);

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 3) throw std::invalid_argument("too few arguments");
    std::vector<int> rank_counts;
    for (int a = 2; a < argc; ++a) rank_counts.push_back(std::stoi(argv[a]));
    const int n = std::stoi(argv[1]);
    if (n < 1 || *std::min_element(rank_counts.begin(), rank_counts.end()) < 1)
      throw std::invalid_argument("N and every P must be >= 1");
    time_cutting(n, rank_counts);
  } catch (const std::exception& error) {
    fmt::print(stderr, "rank_parts_timing: {}\nusage: rank_parts_timing N P... (integers >= 1)\n", error.what());
    return 2;
  }
  return EXIT_SUCCESS;
}

namespace {

void time_cutting(int n, const std::vector<int>& rank_counts) {
  const mesh::Mesh square = mesh::make_paper_square_mesh(n);
  const operators::WholeNumbering whole =
      operators::number_whole_space(square, std::vector<int>(square.n_cells(), 4), nullptr);
  for (int ranks : rank_counts) {
    const auto parts = mesh::bisect_cells(square, ranks, std::vector<int>(square.n_cells(), 1));
    const auto start = std::chrono::steady_clock::now();
    const operators::RankParts cutter(square, whole, parts, ranks, nullptr);
    std::size_t bytes = 0;
    for (int rank = 0; rank < ranks; ++rank) bytes += cutter.bytes_for(rank).size();
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    fmt::print("cells {} ranks {} seconds {:.3f} MB {:.1f}\n", square.n_cells(), ranks, seconds.count(), bytes / 1e6);
  }
}

}  // namespace
