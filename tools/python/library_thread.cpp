// The library thread: a queue of jobs and the thread that runs them, each watching its own
// cancellation token.
#include "library_thread.hpp"

#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

#include "core/interrupt.hpp"

namespace hpcontact::python {
namespace {

struct LibraryThread {
  std::mutex mutex;
  std::condition_variable wake;
  std::deque<std::pair<std::function<void()>, CancellationToken>> jobs;
  bool stopping = false;
  std::thread thread;

  void run() {
    for (;;) {
      std::pair<std::function<void()>, CancellationToken> job;
      {
        std::unique_lock lock(mutex);
        wake.wait(lock, [this] { return stopping || !jobs.empty(); });
        if (jobs.empty()) return;
        job = std::move(jobs.front());
        jobs.pop_front();
      }
      auto& [work, token] = job;
      if (token && token->load()) continue;  // interrupted while it waited
      watch_cancellation(token);
      work();  // (a packaged task: its exception goes to its future)
      watch_cancellation({});
    }
  }
};

LibraryThread& library_thread() {
  static LibraryThread instance;
  return instance;
}

}  // namespace

void post_to_library_thread(std::function<void()> job, CancellationToken token) {
  LibraryThread& library = library_thread();
  const std::lock_guard lock(library.mutex);
  if (!library.thread.joinable()) library.thread = std::thread([&library] { library.run(); });
  library.jobs.emplace_back(std::move(job), std::move(token));
  library.wake.notify_one();
}

void stop_library_thread() {
  LibraryThread& library = library_thread();
  {
    const std::lock_guard lock(library.mutex);
    library.stopping = true;
    library.wake.notify_one();
  }
  if (library.thread.joinable()) library.thread.join();
}

}  // namespace hpcontact::python
