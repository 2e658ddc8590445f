// Process-wide PETSc/SLEPc initialization (once, in the command-line tool) and the split of the
// command line into hpcontact's own arguments and PETSc/SLEPc options (-eps_type arpack, ...).
#pragma once

#include <mpi.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace hpcontact {

/// The command line split in two. PETSc and SLEPc option names contain an underscore after a
/// single dash (-eps_type, -st_type, -eps_view, -log_view, -infsup_eps_tol); such an argument
/// and, when present, its value (the next argument unless that one is itself an option name:
/// "-st_shift -1" keeps -1 as value) go to PETSc. Everything else stays with hpcontact.
struct SplitCommandLine {
  std::vector<std::string> own;    ///< program name first, then hpcontact's arguments
  std::vector<std::string> petsc;  ///< program name first, then PETSc/SLEPc options
};

SplitCommandLine split_petsc_options(int argc, const char* const* argv);

/// RAII: SlepcInitialize (which initializes PETSc and MPI) on construction, or, when not `eager`,
/// on the first ensure_petsc_initialized() of the process; SlepcFinalize on destruction if it was
/// initialized. Create exactly one, in main(). Starting MPI costs a singleton process about 0.3 s
/// (OpenMPI launches its daemon), which a run that needs no PETSc/SLEPc path should not pay.
class PetscSession {
 public:
  explicit PetscSession(const std::vector<std::string>& petsc_arguments, bool eager = true);
  ~PetscSession();
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;
  /// SlepcInitialize with the stored arguments, once. @throws std::runtime_error if it fails.
  void initialize();

 private:
  std::vector<std::string> storage_;
  std::vector<char*> argv_;
  bool initialized_ = false;
  bool errors_as_codes_ = false;  ///< PetscReturnErrorHandler pushed (popped before finalizing)
};

/// Makes SLEPc usable: true if it already is (initialized by anyone), else initializes it through
/// the process's PetscSession; false if there is none (a library user must initialize SLEPc).
bool ensure_petsc_initialized();

/// Whether an MPI launcher started this process (mpirun/mpiexec of OpenMPI or MPICH, srun with
/// PMI/PMIx): then MPI must start at once, since the other ranks wait for it.
bool launched_by_mpi_launcher();

/// This process's rank as the launcher's environment gives it (before MPI is up); 0 without one.
int launcher_rank();

/// (rank, size) in MPI_COMM_WORLD; (0, 1) when MPI is not initialized (unit tests, libraries).
std::pair<int, int> mpi_rank_and_size();

/// (rank, size) in `ranks`; (0, 1) when MPI is not initialized.
std::pair<int, int> rank_and_size(MPI_Comm ranks);

/// Sums data[0 .. count) over `ranks`, in place, so that every one holds the same sum, bit for bit
/// (in chunks: MPI counts are int). Collective on `ranks`; nothing to do on one rank.
void sum_over_ranks(MPI_Comm ranks, double* data, std::size_t count);

}  // namespace hpcontact
