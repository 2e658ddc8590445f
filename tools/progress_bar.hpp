// A one-line progress bar on stderr for long runs (sweeps, studies): only when stderr is a
// terminal, so that logs and pipes stay clean.
#pragma once

#include <fmt/format.h>
#include <unistd.h>

#include <functional>
#include <memory>
#include <string>

#include "core/timer.hpp"

namespace hpcontact::tools {

/// progress(done, total, label) before each step; call `finish_progress_bar` after the last.
inline std::function<void(int, int, const std::string&)> progress_bar(bool enabled) {
  if (!enabled || !isatty(STDERR_FILENO)) return {};
  auto clock = std::make_shared<Stopwatch>();
  return [clock](int done, int total, const std::string& label) {
    const int width = 30, filled = width * done / std::max(total, 1);
    fmt::print(stderr, "\r[{}{}] {}/{} {:.0f}s {:<60.60}", std::string(filled, '#'), std::string(width - filled, '.'),
               done + 1, total, clock->seconds(), label);
  };
}

inline void finish_progress_bar(const std::function<void(int, int, const std::string&)>& bar) {
  if (bar) fmt::print(stderr, "\n");
}

}  // namespace hpcontact::tools
