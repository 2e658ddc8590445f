// The interrupt handlers and their registry of files in progress; the cancellation token each
// thread watches.
#include "core/interrupt.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/syscall.h>
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
std::array<bool, kSlots> is_folder{};

// Removes the files of a flat folder and the folder, with system calls only (opendir and friends
// are not async-signal-safe).
void remove_folder(const char* path) {
  const int fd = open(path, O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  alignas(8) char buffer[8192];
  for (;;) {
    const long n = syscall(SYS_getdents64, fd, buffer, sizeof buffer);
    if (n <= 0) break;
    for (long offset = 0; offset < n;) {
      const auto* entry = reinterpret_cast<const struct dirent64*>(buffer + offset);
      const char* name = entry->d_name;
      if (!(name[0] == '.' && (name[1] == 0 || (name[1] == '.' && name[2] == 0)))) unlinkat(fd, name, 0);
      offset += entry->d_reclen;
    }
  }
  close(fd);
  rmdir(path);
}

std::atomic<bool> announce_interrupt{true};

// write(2) of a text, as the handler may (no stdio).
void write_text(const char* text) {
  for (std::size_t left = std::strlen(text); left > 0;) {
    const ssize_t n = write(STDERR_FILENO, text, left);
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

void on_interrupt(int signal_number) {
  if (announce_interrupt.load()) {
    write_text(signal_number == SIGTERM ? "\nhpcontact: stopped by SIGTERM" : "\nhpcontact: interrupted (SIGINT)");
    write_text("; files in progress removed, finished files kept; exit code 130\n");
  }
  for (int slot = 0; slot < kSlots; ++slot)
    if (armed[slot].load()) is_folder[slot] ? remove_folder(paths[slot].data()) : (void)unlink(paths[slot].data());
  _exit(130);
}

int register_path(const std::string& path, bool folder) {
  if (path.size() >= kPathLength) return -1;
  for (int slot = 0; slot < kSlots; ++slot) {
    bool expected = false;
    if (!claimed[slot].compare_exchange_strong(expected, true)) continue;
    std::memcpy(paths[slot].data(), path.c_str(), path.size() + 1);
    is_folder[slot] = folder;
    armed[slot].store(true);
    return slot;
  }
  return -1;
}

}  // namespace

void install_interrupt_handlers(bool announce) {
  announce_interrupt.store(announce);
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  signal(SIGXFSZ, SIG_IGN);
}

int register_file_in_progress(const std::string& path) { return register_path(path, false); }

int register_folder_in_progress(const std::string& path) { return register_path(path, true); }

void release_file_in_progress(int slot) {
  if (slot < 0 || slot >= kSlots) return;
  armed[slot].store(false);
  claimed[slot].store(false);
}

namespace {
thread_local CancellationToken watched_token;
}  // namespace

void watch_cancellation(CancellationToken token) { watched_token = std::move(token); }

void throw_if_cancelled() {
  if (watched_token && watched_token->load())
    throw Interrupted("interrupted: the work stopped before writing its outputs");
}

}  // namespace hpcontact
