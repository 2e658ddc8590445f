// run_with_products_led_by_first_rank: the first rank's products broadcast to the serving ranks.
#include "contact/led_products.hpp"

#include "core/byte_buffer.hpp"
#include "core/rank_agreement.hpp"

namespace hpcontact::contact {
namespace {

enum Order : int { kDone = 0, kProduct = 1 };

void broadcast_order(int order, MPI_Comm ranks) {
  HPC_VERIFY(MPI_Bcast(&order, 1, MPI_INT, 0, ranks) == MPI_SUCCESS, "broadcasting an order");
}

// The others' side: one product for each order, until the first rank is done.
void serve_products(const TraceOperator& s, MPI_Comm ranks) {
  for (;;) {
    int order = kDone;
    HPC_VERIFY(MPI_Bcast(&order, 1, MPI_INT, 0, ranks) == MPI_SUCCESS, "receiving an order");
    if (order == kDone) return;
    Eigen::VectorXd x(s.size());
    HPC_VERIFY(MPI_Bcast(x.data(), static_cast<int>(x.size()), MPI_DOUBLE, 0, ranks) == MPI_SUCCESS,
               "receiving a vector");
    s(x);
  }
}

}  // namespace

std::vector<char> run_with_products_led_by_first_rank(
    const TraceOperator& s, MPI_Comm ranks, const std::function<std::vector<char>(const TraceOperator&)>& lead) {
  int rank = 0, size = 1;
  MPI_Comm_rank(ranks, &rank);
  MPI_Comm_size(ranks, &size);
  if (size == 1) return lead(s);
  std::vector<char> bytes;
  run_on_all_ranks_agreeing(
      [&] {
        if (rank != 0) return serve_products(s, ranks);
        // A product that fails fails on every rank (the others leave their loop with it); a
        // failure of the method alone must first release them.
        bool in_product = false;
        const TraceOperator led(s.size(), [&](const Eigen::VectorXd& x) {
          broadcast_order(kProduct, ranks);
          Eigen::VectorXd copy = x;
          HPC_VERIFY(MPI_Bcast(copy.data(), static_cast<int>(copy.size()), MPI_DOUBLE, 0, ranks) == MPI_SUCCESS,
                     "broadcasting a vector");
          in_product = true;
          Eigen::VectorXd y = s(copy);
          in_product = false;
          return y;
        });
        try {
          bytes = lead(led);
        } catch (...) {
          if (!in_product) broadcast_order(kDone, ranks);
          throw;
        }
        broadcast_order(kDone, ranks);
      },
      ranks);
  return broadcast_bytes(std::move(bytes), 0, ranks);
}

}  // namespace hpcontact::contact
