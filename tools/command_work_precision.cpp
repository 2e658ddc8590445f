// `hpcontact work-precision STUDY.toml --out DIR`: errors against a far finer reference and wall
// time for families of discretizations of a scene: work_precision.csv, reference.csv, cheapest.csv.
#include <fmt/format.h>

#include <filesystem>

#include "commands.hpp"
#include "core/timer.hpp"
#include "io/atomic_file.hpp"
#include "progress_bar.hpp"
#include "studies/work_precision.hpp"

namespace hpcontact::tools {

void add_work_precision_command(CLI::App& app, CommandAction& action) {
  auto* command = app.add_subcommand("work-precision",
                                     "Work-precision study: error against wall time for families of discretizations");
  auto study_file = std::make_shared<std::string>();
  auto out_dir = std::make_shared<std::string>("results/work_precision");
  command->add_option("study", *study_file, "Study file (TOML), e.g. studies/work_precision/study.toml")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", *out_dir, "Output folder")->capture_default_str();
  command->callback([&action, study_file, out_dir] {
    action = [study_file, out_dir] {
      // 1. Read and check every variant before solving anything.
      const auto study = studies::read_work_precision_study(*study_file);
      io::check_output_directory(*out_dir);
      // 2. Run.
      Stopwatch clock;
      const auto bar = progress_bar(true);
      // (no cost estimate per solve here: the count stands in for the work)
      studies::run_work_precision_study(study, *out_dir, [&](int done, int total, const std::string& label) {
        if (bar) bar(done, total, -1.0, label);
      });
      finish_progress_bar(bar);
      fmt::print("wrote {0}/work_precision.csv, {0}/reference.csv, {0}/cheapest.csv in {1:.1f} s\n", *out_dir,
                 clock.seconds());
      return 0;
    };
  });
}

}  // namespace hpcontact::tools
