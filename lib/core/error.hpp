// Exception types of hpcontact: bad user input versus numerical failure, so that the command line
// can map them to distinct exit codes (2 for input, 3 for numerics).
#pragma once

#include <stdexcept>
#include <string>

namespace hpcontact {

/// Bad input (file, key, value out of range, unparsable expression, broken mesh). The message
/// names the offending input and what is allowed.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A numerical failure (factorization breakdown, no convergence). The message carries residuals.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Builds the standard message "<where>: key '<key>' = <value>: <allowed>".
std::string describe_bad_input(const std::string& where, const std::string& key,
                               const std::string& value, const std::string& allowed);

/// Throws InputError with describe_bad_input(...).
[[noreturn]] void throw_bad_input(const std::string& where, const std::string& key,
                                  const std::string& value, const std::string& allowed);

}  // namespace hpcontact

/// Always-on check of an internal invariant (a bug if it fails, not bad input).
#define HPC_VERIFY(condition, message)                                                  \
  do {                                                                                  \
    if (!(condition))                                                                   \
      throw std::logic_error(std::string(__FILE__) + ":" + std::to_string(__LINE__) +   \
                             ": internal error: " + (message));                         \
  } while (false)
