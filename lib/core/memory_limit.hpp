// How much memory a run may use, and what it is when an allocation fails: the smallest of the
// machine's memory, the address-space limit (ulimit -v, RLIMIT_AS) and the cgroup's memory limit
// (a container's or a batch job's); and the one-time reservation of OpenBLAS's buffer and
// OpenMP's threads, which cannot fail cleanly when memory runs out.
#pragma once

#include <string>

namespace hpcontact {

struct MemoryLimit {
  double bytes = 0.0;
  std::string source;  ///< e.g. "the address-space limit (ulimit -v)"
  /// "<source> of 1.45 GB".
  std::string describe() const;
};

/// The tightest limit on this process's memory, read afresh at each call.
MemoryLimit memory_limit();

/// The message of an allocation that failed (`what`: where, e.g. "in CHOLMOD's factorization of
/// ...", may be empty): names the limit and the way out.
std::string out_of_memory_message(
    const std::string& what,
    const std::string& advice = "use fewer cells, a lower p or fewer ranks per machine, or raise the limit");

/// Makes OpenBLAS take the work buffer of the calling thread, and OpenMP (libgomp, used by CHOLMOD)
/// start its threads, now, while memory is plentiful. OpenBLAS's allocator (0.3.21) retries a
/// failed allocation forever, and libgomp ends the process (exit 1) when it cannot start a thread,
/// so a first call of either near the memory limit hung or ended the run without a word; once
/// taken, buffer and threads serve every later call. Call once at start-up (the command line and
/// the Python module do); what the process has not loaded is skipped.
void reserve_library_buffers();

}  // namespace hpcontact
