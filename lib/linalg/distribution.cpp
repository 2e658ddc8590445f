// Distribution: parsing and naming.
#include "linalg/distribution.hpp"

#include "core/error.hpp"

namespace hpcontact::linalg {

Distribution parse_distributed_solver(const std::string& text, const std::string& origin, const std::string& key) {
  if (text == "substructuring") return Distribution::substructuring;
  if (text == "mumps") return Distribution::mumps;
  if (text == "bddc") return Distribution::bddc;
  throw_bad_input(origin, key, text, "must be one of: substructuring, mumps, bddc");
}

std::string to_string(Distribution distribution) {
  switch (distribution) {
    case Distribution::serial:
      return "serial";
    case Distribution::substructuring:
      return "substructuring";
    case Distribution::mumps:
      return "mumps";
    case Distribution::bddc:
      return "bddc";
  }
  return "?";
}

Distribution distribution_over(int ranks, Distribution choice) { return ranks > 1 ? choice : Distribution::serial; }

}  // namespace hpcontact::linalg
