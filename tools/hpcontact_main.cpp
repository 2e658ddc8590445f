// hpcontact: the command-line tool. Splits PETSc/SLEPc options off the command line, initializes
// SLEPc once, runs one subcommand and maps errors to exit codes (2 bad input, 3 numerical failure).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"

int main(int argc, char** argv) {
  using namespace hpcontact;
  // 1. Separate PETSc/SLEPc options (-eps_type arpack, ...) from our own arguments.
  const SplitCommandLine command_line = split_petsc_options(argc, argv);

  // 2. Declare the subcommands.
  CLI::App app{"hpcontact: higher-order mixed finite elements for model contact problems and "
               "their inf-sup stability.\nPETSc/SLEPc options may be added to any subcommand; the "
               "inf-sup eigensolver reads them with the prefix infsup_ (-infsup_eps_type arpack, "
               "-infsup_eps_view, ...).", "hpcontact"};
  app.set_version_flag("--version", std::string(HPCONTACT_VERSION));
  app.require_subcommand(1);
  tools::CommandAction action;
  tools::add_convergence_command(app, action);
  tools::add_infsup_command(app, action);
  tools::add_sweep_command(app, action);
  tools::add_solve_command(app, action);
  tools::add_benchmark_command(app, action);
  tools::add_work_precision_command(app, action);

  // 3. Parse (CLI11 wants argv without the program name, in reverse order).
  std::vector<std::string> arguments(command_line.own.rbegin(), command_line.own.rend() - 1);
  try {
    app.parse(arguments);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : 2;
  }

  // 4. Run with PETSc/SLEPc initialized once for the whole process.
  try {
    PetscSession session(command_line.petsc);
    return action();
  } catch (const InputError& error) {
    fmt::print(stderr, "hpcontact: error: {}\n", error.what());
    return 2;
  } catch (const NumericalError& error) {
    fmt::print(stderr, "hpcontact: numerical failure: {}\n", error.what());
    return 3;
  } catch (const std::exception& error) {
    fmt::print(stderr, "hpcontact: internal error: {}\n", error.what());
    return 1;
  }
}
