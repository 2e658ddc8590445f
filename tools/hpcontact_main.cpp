// hpcontact: the command-line tool. Splits PETSc/SLEPc options off the command line, initializes
// SLEPc once, runs one subcommand and maps errors to exit codes: 0 ok, 2 bad input, 3 numerical
// failure, 4 I/O failure, 130 interrupted (SIGINT, SIGTERM), 1 a bug.
#include <fmt/format.h>
#include <mpi.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/memory_limit.hpp"
#include "core/petsc_session.hpp"
#include "core/rank_agreement.hpp"
#include "infsup/generalized_eigen.hpp"
#include "io/toml_reader.hpp"

namespace {

// The message for an exit code, printed once: by rank 0 alone for a failure every rank raised
// (agreed inside the work, or met on the failure channel within a few seconds: bad input, a
// refusal, a collective solve that failed), else by the failing rank. A failure of one rank alone
// (an error inside a library's collective operation, e.g. a local solver of PCBDDC) may leave the
// others waiting in a collective call: under mpirun it aborts the whole job, so that no rank hangs.
int report(const std::exception& error) {
  using namespace hpcontact;
  const int code = exit_code_of(error);
  const auto [rank, ranks] = mpi_rank_and_size();
  const bool agreed = failure_shared_by_every_rank();
  if (agreed && rank != 0) return code;
  const char* kind = code == 2   ? "error"
                     : code == 3 ? "numerical failure"
                     : code == 4 ? "I/O failure"
                                 : "internal error";
  fmt::print(stderr, "hpcontact: {}{}: {}\n", kind, ranks > 1 && !agreed ? fmt::format(" on rank {}", rank) : "",
             message_of(error));
  if (ranks > 1 && !agreed) {
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, code);
  }
  return code;
}

// CLI11's "The following arguments were not expected" names no alternative: an option that is a
// typo of one of the subcommand's (--pC for --pc) gets a "did you mean", and every scene-taking
// command is reminded that --set reaches any scene key. Empty if no argument is such an option.
std::string unknown_option_message(const CLI::App& app, const std::vector<std::string>& reversed_arguments) {
  const CLI::App* command = nullptr;
  for (auto it = reversed_arguments.rbegin(); it != reversed_arguments.rend() && !command; ++it)
    for (const auto* sub : app.get_subcommands([](const CLI::App*) { return true; }))
      if (sub->get_name() == *it) command = sub;
  if (!command) return "";
  std::vector<std::string> names;
  bool takes_set = false;
  for (const auto* option : command->get_options()) {
    for (const auto& name : option->get_lnames()) names.push_back("--" + name);
    for (const auto& name : option->get_snames()) names.push_back("-" + name);
    takes_set = takes_set || option->check_lname("set");
  }
  for (auto it = reversed_arguments.rbegin(); it != reversed_arguments.rend(); ++it) {
    if (it->size() < 2 || (*it)[0] != '-' || std::isdigit(static_cast<unsigned char>((*it)[1]))) continue;
    const std::string name = it->substr(0, it->find('='));
    if (std::find(names.begin(), names.end(), name) != names.end()) continue;
    const auto nearest = hpcontact::io::nearest_name(name, names);
    return fmt::format("hpcontact {}: unknown option '{}'{}{}; 'hpcontact {} --help' lists the options",
                       command->get_name(), name, nearest ? fmt::format(" (did you mean '{}'?)", *nearest) : "",
                       takes_set ? "; any scene key can be set with --set KEY=VALUE" : "", command->get_name());
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace hpcontact;
  install_interrupt_handlers(launcher_rank() == 0);
  // 1. Separate PETSc/SLEPc options (-eps_type arpack, ...) from our own arguments.
  const SplitCommandLine command_line = split_petsc_options(argc, argv);

  // 2. Declare the subcommands.
  CLI::App app{
      "hpcontact: higher-order mixed finite elements for model contact problems and "
      "their inf-sup stability.\nPETSc/SLEPc options may be added to any subcommand; the "
      "inf-sup eigensolver reads them with the prefix infsup_ (-infsup_eps_type arpack, "
      "-infsup_eps_view, ...).",
      "hpcontact"};
  app.set_version_flag("--version", std::string(HPCONTACT_VERSION));
  app.require_subcommand(1);
  tools::CommandAction action;
  tools::add_convergence_command(app, action);
  tools::add_infsup_command(app, action);
  tools::add_advise_command(app, action);
  tools::add_sweep_command(app, action);
  tools::add_solve_command(app, action);
  tools::add_benchmark_command(app, action);
  tools::add_work_precision_command(app, action);
  tools::add_hertz_command(app, action);
  tools::add_scene_keys_command(app, action);

  // 3. Parse (CLI11 wants argv without the program name, in reverse order).
  std::vector<std::string> arguments(command_line.own.rbegin(), command_line.own.rend() - 1);
  const std::vector<std::string> given = arguments;  // (parse consumes its argument)
  try {
    app.parse(arguments);
  } catch (const CLI::ParseError& error) {
    // Under a launcher every rank parses the same line: rank 0 alone prints and returns the exit
    // code (MPI is not up yet, so the launcher's rank variable tells). The other ranks end quietly
    // with 0: a non-zero exit of theirs could make the launcher kill rank 0 before it printed.
    if (launcher_rank() != 0) return 0;
    if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
      if (const auto message = unknown_option_message(app, given); !message.empty()) {
        fmt::print(stderr, "{}\n", message);
        return 2;
      }
    }
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  }

  // 4. Run with PETSc/SLEPc initialized once for the whole process: at once under an MPI launcher
  // or with PETSc options, else when a PETSc/SLEPc path first runs (a solve needing none starts
  // as fast as --version). A failure is reported while MPI is still up (finalizing first could
  // leave the message unprinted).
  std::unique_ptr<PetscSession> session;
  try {
    reserve_library_buffers();
    const bool eager = launched_by_mpi_launcher() || command_line.petsc.size() > 1;
    session = std::make_unique<PetscSession>(command_line.petsc, eager);
    open_failure_channel();
  } catch (const OutOfMemory& error) {
    // Too little memory to start: an OpenBLAS thread may be retrying its buffer forever, and the
    // library's exit handler would wait for it.
    report(error);
    std::fflush(stderr);
    _exit(exit_code_of(error));
  } catch (const std::exception& error) {
    return report(error);
  }
  int code = 0;
  try {
    run_on_all_ranks_agreeing([&] { infsup::check_petsc_options(command_line.petsc); });
    code = action();
  } catch (const std::exception& error) {
    code = report(error);
  }
  session.reset();
  return code;
}
