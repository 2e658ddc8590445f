// SIGINT and SIGTERM: files being written are removed and the process exits with 130, so an
// interrupted run leaves no temporary file behind (finished files stay: they were renamed into
// place whole). SIGXFSZ is ignored, so that a file size limit is an I/O error, not a crash. And the
// cooperative cancellation by which another thread stops library work.
#pragma once

#include <atomic>
#include <memory>
#include <stdexcept>
#include <string>

namespace hpcontact {

/// Installs the handlers (once per process; the command line calls it first). With `announce` the
/// handler prints one line ("hpcontact: interrupted (SIGINT); ...") before it exits; under mpirun
/// rank 0 alone announces, since mpirun sends the signal to every rank.
void install_interrupt_handlers(bool announce = true);

/// A file the handlers remove on an interrupt until it is released. At most 64 at once; returns
/// the slot to release, or -1 if all are taken (the file is then not removed on an interrupt).
int register_file_in_progress(const std::string& path);
void release_file_in_progress(int slot);

/// The same for a folder of outputs in progress: its files (not subfolders) and the folder itself
/// are removed on an interrupt.
int register_folder_in_progress(const std::string& path);

/// Library work stopped at a cancellation point (see request_cancellation).
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Cooperative cancellation of library work running on another thread (the Python module runs its
/// work on a thread of its own and answers Ctrl-C at once): the token of a piece of work, set by
/// the thread that asked for it, makes the work stop with Interrupted at its next cancellation
/// point (between a sweep's points, a run's stages, and before any output is committed), so that
/// an interrupted run writes nothing.
using CancellationToken = std::shared_ptr<std::atomic<bool>>;
/// The token the calling thread's work checks from now on (empty: none, never cancelled).
void watch_cancellation(CancellationToken token);
/// @throws Interrupted if the token the calling thread watches is set.
void throw_if_cancelled();

}  // namespace hpcontact
