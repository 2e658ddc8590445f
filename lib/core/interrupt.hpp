// SIGINT and SIGTERM: files being written are removed and the process exits with 130, so an
// interrupted run leaves no temporary file behind (finished files stay: they were renamed into
// place whole). SIGXFSZ is ignored, so that a file size limit is an I/O error, not a crash.
#pragma once

#include <string>

namespace hpcontact {

/// Installs the handlers (once per process; the command line calls it first).
void install_interrupt_handlers();

/// A file the handlers remove on an interrupt until it is released. At most 64 at once; returns
/// the slot to release, or -1 if all are taken (the file is then not removed on an interrupt).
int register_file_in_progress(const std::string& path);
void release_file_in_progress(int slot);

/// The same for a folder of outputs in progress: its files (not subfolders) and the folder itself
/// are removed on an interrupt.
int register_folder_in_progress(const std::string& path);

}  // namespace hpcontact
