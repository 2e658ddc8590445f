// The thread on which the Python module runs the library's long calls (solve, sweep, advise), so
// that the interpreter's own thread stays free to answer Ctrl-C: it waits for the call in short
// steps, checking Python's signals, and on KeyboardInterrupt returns at once while the call stops
// at its next cancellation point (core/interrupt.hpp) without writing anything. One thread for all
// calls keeps PETSc and MPI on the thread that started them; calls run one at a time.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <future>
#include <memory>

#include "core/interrupt.hpp"

namespace hpcontact::python {

/// Posts `job` to the library thread (started on first use); jobs run in order, each watching
/// its `token` (core/interrupt.hpp); a job whose token is set before it starts does not run.
void post_to_library_thread(std::function<void()> job, CancellationToken token = {});
/// Runs the jobs still queued, then ends the thread (at interpreter exit: the PETSc session is
/// finalized there by a last job).
void stop_library_thread();

/// Runs `work` on the library thread and returns its result, or rethrows its exception. Call with
/// the GIL held: it is released while waiting. On a signal whose Python handler raises
/// (KeyboardInterrupt), the work's token is set and the handler's exception is raised within
/// 0.05 s; the work then stops at its next cancellation point, or never starts.
template <class Work>
auto run_interruptibly(Work work) -> decltype(work()) {
  using Result = decltype(work());
  auto task = std::make_shared<std::packaged_task<Result()>>(std::move(work));
  auto done = task->get_future();
  const auto token = std::make_shared<std::atomic<bool>>(false);
  post_to_library_thread([task] { (*task)(); }, token);
  for (;;) {
    {
      pybind11::gil_scoped_release release;
      if (done.wait_for(std::chrono::milliseconds(50)) == std::future_status::ready) break;
    }
    if (PyErr_CheckSignals() != 0) {
      token->store(true);
      throw pybind11::error_already_set();
    }
  }
  return done.get();
}

}  // namespace hpcontact::python
