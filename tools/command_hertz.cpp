// `hpcontact hertz STUDY.toml --out DIR`: the elastic contact pressure against the 2-D Hertz
// solution along refinement sequences; writes DIR/hertz.csv and DIR/hertz_profiles.csv and prints
// one line per run.
#include <fmt/format.h>

#include <filesystem>

#include "commands.hpp"
#include "io/atomic_file.hpp"
#include "studies/hertz_study.hpp"

namespace hpcontact::tools {

void add_hertz_command(CLI::App& app, CommandAction& action) {
  auto* command = app.add_subcommand(
      "hertz", "Elastic contact pressure against the 2-D Hertz solution under h-, p- and hp-refinement (CSV)");
  auto study_file = std::make_shared<std::string>();
  auto out_dir = std::make_shared<std::string>("results/hertz");
  command->add_option("study", *study_file, "Study file (TOML), e.g. studies/elasticity/hertz_study.toml")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", *out_dir, "Output folder for hertz.csv and hertz_profiles.csv")->capture_default_str();
  command->callback([&action, study_file, out_dir] {
    action = [study_file, out_dir] {
      // 1. Read and check every level's scene before any work.
      const auto study = studies::read_hertz_study(*study_file);
      io::ensure_writable_directory(*out_dir);
      // 2. Run, one line per level.
      fmt::print("{:>9} {:>5} {:>3} {:>3} {:>8} {:>11} {:>10} {:>10} {:>10} {:>10} {:>8}\n", "sequence", "level", "p",
                 "pC", "ndofs", "P", "a_hertz", "a_error", "profile", "seconds", "");
      const auto results = studies::run_hertz_study(study, [](const studies::HertzRow& row) {
        fmt::print("{:>9} {:>5} {:>3} {:>3} {:>8} {:>11.5e} {:>10.5f} {:>10.2e} {:>10.2e} {:>10.3f}  {}\n",
                   row.sequence, row.level, row.p, row.pc, row.ndofs, row.total_force, row.hertz_half_width,
                   row.half_width_error, row.profile_error, row.seconds, row.label);
        std::fflush(stdout);
      });
      // 3. Save.
      const std::filesystem::path out(*out_dir);
      studies::hertz_table(results.rows).write(out / "hertz.csv");
      results.profiles.write(out / "hertz_profiles.csv");
      fmt::print("wrote {} and {}\n", (out / "hertz.csv").string(), (out / "hertz_profiles.csv").string());
      return 0;
    };
  });
}

}  // namespace hpcontact::tools
