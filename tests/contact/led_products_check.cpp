// Helper of led_products_test, run under mpirun: a collective operator (each product sums every
// rank's share over the ranks, so all must make it together) led by the first rank through a
// method whose step count differs from rank to rank were each to run it (rank r would take
// 5 + r steps). Modes: "ok" prints each rank's product count and the result every rank got;
// "method_fails" makes the first rank's method throw after 3 products; "product_fails" makes
// the 3rd product throw on every rank. A failure prints "failed: <message>" and exits 3.
//
//   led_products_check ok|method_fails|product_fails
#include <fmt/format.h>
#include <mpi.h>

#include <string>

#include "contact/led_products.hpp"
#include "core/byte_buffer.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"

using namespace hpcontact;

int main(int argc, char** argv) {
  const PetscSession session({argv[0]});
  if (argc != 2) return 2;
  const std::string mode = argv[1];
  // (plain ints: clang 14 does not capture structured bindings in lambdas)
  const int rank = mpi_rank_and_size().first, size = mpi_rank_and_size().second;
  long made = 0;
  const contact::TraceOperator s(4, [&](const Eigen::VectorXd& x) {
    if (mode == "product_fails" && made == 2) throw NumericalError("the third product failed");
    ++made;
    Eigen::VectorXd y = (rank + 1.0) * x;  // Σ_r (r + 1) x over the ranks
    sum_over_ranks(MPI_COMM_WORLD, y.data(), static_cast<std::size_t>(y.size()));
    return y;
  });
  try {
    const auto bytes = contact::run_with_products_led_by_first_rank(s, MPI_COMM_WORLD, [&](const auto& led) {
      Eigen::VectorXd x = Eigen::VectorXd::Ones(4);
      for (int step = 0; step < 5 + rank; ++step) {
        if (mode == "method_fails" && step == 3) throw NumericalError("the method failed");
        x = led(x) / (size * (size + 1) / 2.0);
      }
      ByteWriter out;
      out.put(x.sum());
      return out.take();
    });
    ByteReader in(bytes);
    fmt::print("rank {} products {} result {:.17g}\n", rank, made, in.get<double>());
  } catch (const NumericalError& error) {
    fmt::print("rank {} failed: {}\n", rank, error.what());
    return 3;
  }
  return 0;
}
