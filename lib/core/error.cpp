// Message helpers for InputError.
#include "core/error.hpp"

namespace hpcontact {

std::string describe_bad_input(const std::string& where, const std::string& key,
                               const std::string& value, const std::string& allowed) {
  std::string message = where.empty() ? std::string() : where + ": ";
  message += "key '" + key + "' = " + value + ": " + allowed;
  return message;
}

void throw_bad_input(const std::string& where, const std::string& key, const std::string& value,
                     const std::string& allowed) {
  throw InputError(describe_bad_input(where, key, value, allowed));
}

}  // namespace hpcontact
