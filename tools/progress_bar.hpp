// Progress of long runs (sweeps, studies) on stderr, whatever stderr is: a one-line bar on a
// terminal; in a log, a pipe or a notebook a plain line at most every few seconds (count, elapsed
// time, estimated time left), so that a long run is never silent and a short one stays quiet.
#pragma once

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <functional>
#include <memory>
#include <string>

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

/// progress(done, total, label) before each step; call `finish_progress_bar` after the last.
inline std::function<void(int, int, const std::string&)> progress_bar(bool enabled) {
  if (!enabled) return {};
  auto clock = std::make_shared<Stopwatch>();
  if (isatty(STDERR_FILENO))
    return [clock](int done, int total, const std::string& label) {
      const int width = 30, filled = width * done / std::max(total, 1);
      fmt::print(stderr, "\r[{}{}] {}/{} {:.0f}s {:<60.60}", std::string(filled, '#'), std::string(width - filled, '.'),
                 done + 1, total, clock->seconds(), label);
    };
  auto last = std::make_shared<double>(0.0);
  return [clock, last, interval = progress_interval()](int done, int total, const std::string& label) {
    const double elapsed = clock->seconds();
    if (elapsed - *last < interval) return;
    *last = elapsed;
    const std::string left =
        done > 0 ? fmt::format("about {:.0f} s left", elapsed / done * (total - done)) : "time left not known yet";
    fmt::print(stderr, "progress: {}/{} done in {:.0f} s, {}; next: {}\n", done, total, elapsed, left, label);
  };
}

inline void finish_progress_bar(const std::function<void(int, int, const std::string&)>& bar) {
  if (bar && isatty(STDERR_FILENO)) fmt::print(stderr, "\n");
}

}  // namespace hpcontact::tools
