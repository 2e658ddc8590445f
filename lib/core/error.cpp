// Message helpers for InputError and IoError; exit codes; the reported message of an exception.
#include "core/error.hpp"

#include <cerrno>
#include <cstring>
#include <new>

#include "core/memory_limit.hpp"

namespace hpcontact {

std::string describe_bad_input(const std::string& where, const std::string& key, const std::string& value,
                               const std::string& allowed) {
  std::string message = where.empty() ? std::string() : where + ": ";
  message += "key '" + key + "' = " + value + ": " + allowed;
  return message;
}

void throw_bad_input(const std::string& where, const std::string& key, const std::string& value,
                     const std::string& allowed) {
  throw InputError(describe_bad_input(where, key, value, allowed));
}

std::string describe_io_failure(const std::string& what, const std::string& path) {
  const int error = errno;
  return what + " '" + path + "': " + (error != 0 ? std::strerror(error) : "unknown reason");
}

int exit_code_of(const std::exception& error) {
  if (dynamic_cast<const InputError*>(&error)) return 2;
  if (dynamic_cast<const NumericalError*>(&error) || dynamic_cast<const std::bad_alloc*>(&error)) return 3;
  if (dynamic_cast<const IoError*>(&error)) return 4;
  return 1;
}

std::string message_of(const std::exception& error) noexcept {
  if (!dynamic_cast<const std::bad_alloc*>(&error)) return error.what();
  try {
    return out_of_memory_message("");
  } catch (...) {  // (the message itself needs memory; callers report from catch blocks)
    return "out of memory";
  }
}

}  // namespace hpcontact
