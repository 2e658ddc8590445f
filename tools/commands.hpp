// Registration of the hpcontact subcommands; each lives in its own command_<name>.cpp.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace hpcontact::tools {

/// A subcommand's action, run after parsing; returns the process exit code.
using CommandAction = std::function<int()>;

/// The help of --distributed-solver (solve, infsup): one process's factorizations over
/// the ranks; named, a solver runs on one rank too.
inline constexpr const char* kDistributedSolverHelp =
    "substructuring (CHOLMOD per rank, dense interface) | mumps (MPIAIJ + MUMPS; out of core with "
    "PETSC_OPTIONS='-mat_mumps_icntl_22 1') | bddc (MATIS + CG with PCBDDC) | gamg (MPIAIJ + CG with PCGAMG, no "
    "factor). Default: substructuring under "
    "mpirun, CHOLMOD on one rank, where a named solver runs too";

/// Adds `convergence` to the app; sets `action` when the subcommand is chosen.
void add_convergence_command(CLI::App& app, CommandAction& action);

/// Adds `sweep`.
void add_sweep_command(CLI::App& app, CommandAction& action);

/// Adds `solve`.
void add_solve_command(CLI::App& app, CommandAction& action);

/// Adds `benchmark`.
void add_benchmark_command(CLI::App& app, CommandAction& action);

/// Adds `work-precision`.
void add_work_precision_command(CLI::App& app, CommandAction& action);

/// Adds `infsup`.
void add_infsup_command(CLI::App& app, CommandAction& action);

/// Adds `advise`.
void add_advise_command(CLI::App& app, CommandAction& action);

/// Adds `hertz`.
void add_hertz_command(CLI::App& app, CommandAction& action);

/// Adds `scene-keys`.
void add_scene_keys_command(CLI::App& app, CommandAction& action);

}  // namespace hpcontact::tools
