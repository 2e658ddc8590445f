// Lookups on a run's result.
#include "driver/run_result.hpp"

#include <algorithm>
#include <stdexcept>

namespace hpcontact::driver {

const ContactResult& RunResult::contact(const std::string& problem) const {
  const auto found =
      std::find_if(contacts.begin(), contacts.end(), [&](const ContactResult& c) { return c.problem == problem; });
  if (found == contacts.end()) throw std::out_of_range("the run solved no contact problem '" + problem + "'");
  return *found;
}

}  // namespace hpcontact::driver
