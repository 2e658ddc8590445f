// `hpcontact convergence STUDY.toml --out DIR`: h- and p-convergence of S^p(T_h) against a
// manufactured solution; writes DIR/convergence.csv and prints a table with observed rates.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "commands.hpp"
#include "io/atomic_file.hpp"
#include "studies/convergence_study.hpp"

namespace hpcontact::tools {

void add_convergence_command(CLI::App& app, CommandAction& action) {
  auto* command =
      app.add_subcommand("convergence", "Convergence of S^p(T_h) against a manufactured solution (CSV: errors, rates)");
  auto study_file = std::make_shared<std::string>();
  auto out_dir = std::make_shared<std::string>("results/convergence");
  command->add_option("study", *study_file, "Study file (TOML), e.g. studies/convergence/study.toml")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", *out_dir, "Output folder for convergence.csv")->capture_default_str();
  command->callback([&action, study_file, out_dir] {
    action = [study_file, out_dir] {
      // 1. Read and check the study before any work, so bad input fails fast.
      const auto study = studies::read_convergence_study(*study_file);
      io::ensure_writable_directory(*out_dir);
      // 2. Run, printing one line per point with the observed rate against the previous h (same p
      //    and geometry).
      fmt::print("{:>3} {:>7} {:>10} {:>9} {:>12} {:>12} {:>6} {:>12} {:>9}\n", "p", "cells", "geometry", "ndofs", "h",
                 "error_h1", "rate", "error_l2", "seconds");
      std::map<std::pair<int, std::string>, studies::ConvergenceRow> previous;
      const auto rows = studies::run_convergence_study(study, [&](const auto& row) {
        std::string rate = "-";
        const std::pair key{row.point.p, row.point.geometry};
        if (auto it = previous.find(key); it != previous.end() && it->second.h != row.h)
          rate = fmt::format("{:.2f}", std::log(it->second.error_h1 / row.error_h1) / std::log(it->second.h / row.h));
        previous[key] = row;
        fmt::print("{:>3} {:>7} {:>10} {:>9} {:>12.4e} {:>12.4e} {:>6} {:>12.4e} {:>9.3f}\n", row.point.p, row.cells,
                   row.point.geometry, row.ndofs, row.h, row.error_h1, rate, row.error_l2, row.seconds);
        std::fflush(stdout);
      });
      // 3. Save.
      const auto path = std::filesystem::path(*out_dir) / "convergence.csv";
      studies::convergence_table(rows).write(path);
      fmt::print("wrote {}\n", path.string());
      return 0;
    };
  });
}

}  // namespace hpcontact::tools
