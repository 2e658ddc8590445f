// `hpcontact benchmark FILE.toml --out DIR`: the performance benchmark (contact solves and α as
// ratios to one linear solve of the same matrix, timed in the same run) into DIR/benchmark.csv,
// and the fitted scaling exponents into DIR/scaling.csv.
#include <fmt/format.h>

#include <filesystem>

#include "commands.hpp"
#include "io/atomic_file.hpp"
#include "studies/performance_benchmark.hpp"

namespace hpcontact::tools {

void add_benchmark_command(CLI::App& app, CommandAction& action) {
  auto* command =
      app.add_subcommand("benchmark", "Timings as ratios to one linear solve: benchmark.csv and scaling.csv");
  auto file = std::make_shared<std::string>();
  auto out_dir = std::make_shared<std::string>("results/performance");
  command->add_option("benchmark", *file, "Benchmark file (TOML), e.g. studies/performance/benchmark.toml")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", *out_dir, "Output folder")->capture_default_str();
  command->callback([&action, file, out_dir] {
    action = [file, out_dir] {
      // 1. Read and check the benchmark, and the output folder, before timing anything.
      auto benchmark = studies::read_performance_benchmark(*file);
      benchmark.executable = std::filesystem::read_symlink("/proc/self/exe").string();
      io::check_output_directory(*out_dir);
      // 2. Run, one line per row on stderr (the large levels take minutes).
      fmt::print(stderr, "{:>10} {:>5} {:>9} {:>9} {:>9} {:>7} {:>8}\n", "kind", "n", "ndofs", "baseline", "seconds",
                 "ratio", "peak MB");
      const auto rows = studies::run_performance_benchmark(benchmark, [](const studies::BenchmarkRow& r) {
        fmt::print(stderr, "{:>10} {:>5} {:>9} {:>9.3f} {:>9.3f} {:>7.3f} {:>8.0f}\n", r.kind, r.n, r.ndofs,
                   r.seconds_baseline, r.seconds, r.ratio, r.peak_rss_mb);
      });
      // 3. Save.
      const std::filesystem::path out(*out_dir);
      io::ensure_writable_directory(out);
      studies::benchmark_table(rows).write(out / "benchmark.csv");
      studies::scaling_exponents(rows).write(out / "scaling.csv");
      fmt::print("wrote {}/benchmark.csv and scaling.csv ({} rows)\n", out.string(), rows.size());
      return 0;
    };
  });
}

}  // namespace hpcontact::tools
