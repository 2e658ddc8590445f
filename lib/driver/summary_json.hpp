// summary.json: the one place a run's typed result becomes JSON.
#pragma once

#include <string>

#include "driver/run_result.hpp"

namespace hpcontact::driver {

/// The run as summary.json's text (indented, ending in a newline): one entry per contact problem
/// under its name, "infsup", "convergence", "operators", the discretization and the timings.
std::string summary_json(const RunResult& result);

}  // namespace hpcontact::driver
