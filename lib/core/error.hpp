// Exception types of hpcontact, one per exit code of the command line: 2 bad input, 3 numerical
// failure, 4 I/O failure (1 is left for bugs, 130 for an interrupt).
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

/// An allocation that failed (a library's report of it; std::bad_alloc is treated alike): exit 3,
/// with a message naming the memory limit (out_of_memory_message in core/memory_limit.hpp).
class OutOfMemory : public NumericalError {
 public:
  using NumericalError::NumericalError;
};

/// An I/O failure on a path the input was right to name (disk full, file size limit, a folder
/// removed under a run). The message names the path and the system's reason.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// "<what> '<path>': <strerror(errno)>" for the current errno.
std::string describe_io_failure(const std::string& what, const std::string& path);

/// The exit code of the command line for an exception: 2, 3 (std::bad_alloc included), 4, or 1 (a
/// bug).
int exit_code_of(const std::exception& error);

/// The message of an exception as reported: what() but for std::bad_alloc, whose what() says
/// nothing, the out-of-memory message naming the memory limit.
std::string message_of(const std::exception& error) noexcept;

/// Builds the standard message "<where>: key '<key>' = <value>: <allowed>".
std::string describe_bad_input(const std::string& where, const std::string& key, const std::string& value,
                               const std::string& allowed);

/// Throws InputError with describe_bad_input(...).
[[noreturn]] void throw_bad_input(const std::string& where, const std::string& key, const std::string& value,
                                  const std::string& allowed);

}  // namespace hpcontact

/// Always-on check of an internal invariant (a bug if it fails, not bad input).
#define HPC_VERIFY(condition, message)                                                \
  do {                                                                                \
    if (!(condition))                                                                 \
      throw std::logic_error(std::string(__FILE__) + ":" + std::to_string(__LINE__) + \
                             ": internal error: " + (message));                       \
  } while (false)
