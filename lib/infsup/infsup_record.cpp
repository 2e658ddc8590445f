// The α record made from a result and the facts of its pairing.
#include "infsup/infsup_record.hpp"

#include <algorithm>

namespace hpcontact::infsup {

InfSupRecord make_infsup_record(const PairingFacts& pairing, const InfSupResult& result) {
  InfSupRecord record;
  record.problem = pairing.problem;
  record.norm = pairing.norm;
  record.p = pairing.p;
  record.pc = pairing.pc;
  record.family = pairing.family;
  record.level = pairing.level;
  record.n = pairing.n;
  record.m = pairing.m;
  record.h = result.h;
  record.h_min = pairing.h_min;
  record.H = result.H;
  record.ratio = pairing.ratio ? *pairing.ratio : static_cast<double>(pairing.m) / pairing.n;
  record.pi = result.pi;
  record.alpha = result.alpha;
  record.alpha_error = result.alpha_error;
  record.alpha_converged = result.alpha_converged;
  record.ndofs = result.n_primal_dofs;
  record.nmult = result.n_multiplier_dofs;
  record.seconds = result.seconds;
  return record;
}

double shortest_contact_edge(const mesh::ContactBoundary& contact) {
  const auto nodes = contact.breakpoints();
  double shortest = nodes.back() - nodes.front();
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) shortest = std::min(shortest, nodes[k + 1] - nodes[k]);
  return shortest;
}

}  // namespace hpcontact::infsup
