// The interrupt handlers and their registry of files in progress.
#include "core/interrupt.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>

namespace hpcontact {
namespace {

constexpr int kSlots = 64;
constexpr std::size_t kPathLength = 4096;
// A slot is claimed by one writer, then armed once its path is written: the handler reads armed
// slots only, without locks.
std::array<std::atomic<bool>, kSlots> claimed{}, armed{};
std::array<std::array<char, kPathLength>, kSlots> paths{};

void on_interrupt(int) {
  for (int slot = 0; slot < kSlots; ++slot)
    if (armed[slot].load()) unlink(paths[slot].data());  // async-signal-safe
  _exit(130);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  signal(SIGXFSZ, SIG_IGN);
}

int register_file_in_progress(const std::string& path) {
  if (path.size() >= kPathLength) return -1;
  for (int slot = 0; slot < kSlots; ++slot) {
    bool expected = false;
    if (!claimed[slot].compare_exchange_strong(expected, true)) continue;
    std::memcpy(paths[slot].data(), path.c_str(), path.size() + 1);
    armed[slot].store(true);
    return slot;
  }
  return -1;
}

void release_file_in_progress(int slot) {
  if (slot < 0 || slot >= kSlots) return;
  armed[slot].store(false);
  claimed[slot].store(false);
}

}  // namespace hpcontact
