// The message of the InputError an action throws, for tests that check what a user is told.
#pragma once

#include <functional>
#include <string>

#include "core/error.hpp"

namespace hpcontact::testing {

/// What `action` says when it throws InputError; "(no InputError thrown)" when it does not.
inline std::string message_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no InputError thrown)";
}

}  // namespace hpcontact::testing
