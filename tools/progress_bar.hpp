// Progress of long runs (sweeps, studies) on stderr, whatever stderr is: a one-line bar on a
// terminal; in a log, a pipe or a notebook a plain line at most every few seconds (count, elapsed
// time, estimated time left), so that a long run is never silent and a short one stays quiet.
// The estimate is by the run's own cost estimate where it has one (a sweep's plan weighs a
// point by its mesh and degree), else by the count; while one unit runs past the interval, a
// heartbeat line says which and for how long.
#pragma once

#include <fmt/format.h>
#include <unistd.h>

#include <condition_variable>
#include <cstdlib>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "core/timer.hpp"

namespace hpcontact::tools {

/// Seconds between two plain progress lines: HPCONTACT_PROGRESS_SECONDS if set (a number ≥ 0;
/// 0 prints every step), else 5.
inline double progress_interval() {
  const char* text = std::getenv("HPCONTACT_PROGRESS_SECONDS");
  if (!text || !*text) return 5.0;
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  return (*end == '\0' && value >= 0.0) ? value : 5.0;
}

/// progress(done, total, work_done, label) before each step: `done` of `total` steps finished,
/// `work_done` the estimated fraction of the work they make up (negative: no estimate, done/total
/// stands in), `label` the step starting.
using ProgressReport = std::function<void(int done, int total, double work_done, const std::string& label)>;

namespace detail {

// The plain lines: one at a step when the interval has passed since the last, and from a thread
// of its own one every interval while a step runs longer.
class ProgressLines {
 public:
  explicit ProgressLines(double interval) : interval_(interval) {
    if (interval_ > 0.0) heartbeat_ = std::thread([this] { beat(); });
  }
  ~ProgressLines() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    if (heartbeat_.joinable()) heartbeat_.join();
  }
  ProgressLines(const ProgressLines&) = delete;
  ProgressLines& operator=(const ProgressLines&) = delete;

  void step(int done, int total, double work_done, const std::string& label) {
    std::lock_guard lock(mutex_);
    // (the clock starts with the first step: reading and planning are no part of the rate)
    if (total_ == 0) clock_ = Stopwatch();
    done_ = done, total_ = total, label_ = label, step_started_ = clock_.seconds();
    work_done_ = work_done >= 0.0 ? work_done : (total > 0 ? static_cast<double>(done) / total : 0.0);
    if (step_started_ - last_line_ >= interval_) print("next", step_started_);
  }

 private:
  void beat() {
    std::unique_lock lock(mutex_);
    while (!stopping_) {
      wake_.wait_for(lock, std::chrono::duration<double>(interval_ / 4));
      const double now = clock_.seconds();
      if (!stopping_ && total_ > 0 && now - last_line_ >= interval_) print("running", now);
    }
  }
  // (mutex_ held)
  void print(const char* what, double now) {
    last_line_ = now;
    const std::string left = work_done_ > 0.0 ? fmt::format("about {:.0f} s left", now / work_done_ * (1 - work_done_))
                                              : "time left not known yet";
    const std::string running = std::string(what) == "running"
                                    ? fmt::format("; running for {:.0f} s: {}", now - step_started_, label_)
                                    : fmt::format("; next: {}", label_);
    fmt::print(stderr, "progress: {}/{} done in {:.0f} s, {}{}\n", done_, total_, now, left, running);
  }

  const double interval_;
  Stopwatch clock_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  int done_ = 0, total_ = 0;
  double work_done_ = 0.0, step_started_ = 0.0, last_line_ = 0.0;
  std::string label_;
  std::thread heartbeat_;
};

}  // namespace detail

/// The report for a run; call `finish_progress_bar` after the last step (the heartbeat stops
/// when the last copy of the report is destroyed).
inline ProgressReport progress_bar(bool enabled) {
  if (!enabled) return {};
  if (isatty(STDERR_FILENO)) {
    auto clock = std::make_shared<Stopwatch>();
    return [clock](int done, int total, double work_done, const std::string& label) {
      const double fraction = work_done >= 0.0 ? work_done : static_cast<double>(done) / std::max(total, 1);
      const int width = 30, filled = std::clamp(static_cast<int>(width * fraction), 0, width);
      fmt::print(stderr, "\r[{}{}] {}/{} {:.0f}s {:<60.60}", std::string(filled, '#'), std::string(width - filled, '.'),
                 done + 1, total, clock->seconds(), label);
    };
  }
  auto lines = std::make_shared<detail::ProgressLines>(progress_interval());
  return [lines](int done, int total, double work_done, const std::string& label) {
    lines->step(done, total, work_done, label);
  };
}

inline void finish_progress_bar(const ProgressReport& bar) {
  if (bar && isatty(STDERR_FILENO)) fmt::print(stderr, "\n");
}

}  // namespace hpcontact::tools
