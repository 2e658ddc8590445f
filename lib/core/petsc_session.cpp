// PetscSession, split_petsc_options and the MPI helpers (rank and size, sums over the ranks).
#include "core/petsc_session.hpp"

#include <mpi.h>
#include <slepcsys.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <regex>
#include <stdexcept>

#include "core/error.hpp"

namespace hpcontact {
namespace {

bool is_petsc_option_name(const std::string& argument) {
  static const std::regex pattern("^-[A-Za-z][A-Za-z0-9]*_[A-Za-z0-9_]*$");
  return std::regex_match(argument, pattern);
}

bool looks_like_option_name(const std::string& argument) {
  return argument.size() > 1 && argument[0] == '-' &&
         (std::isalpha(static_cast<unsigned char>(argument[1])) || argument[1] == '-');
}

}  // namespace

SplitCommandLine split_petsc_options(int argc, const char* const* argv) {
  SplitCommandLine split;
  const std::string program = argc > 0 ? argv[0] : "hpcontact";
  split.own.push_back(program);
  split.petsc.push_back(program);
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (!is_petsc_option_name(argument)) {
      split.own.push_back(argument);
      continue;
    }
    split.petsc.push_back(argument);
    if (i + 1 < argc && !looks_like_option_name(argv[i + 1])) split.petsc.push_back(argv[++i]);
  }
  return split;
}

namespace {

std::mutex session_mutex;
PetscSession* lazy_session = nullptr;  // the process's session, until it is destroyed

}  // namespace

PetscSession::PetscSession(const std::vector<std::string>& petsc_arguments, bool eager) : storage_(petsc_arguments) {
  for (auto& argument : storage_) argv_.push_back(argument.data());
  argv_.push_back(nullptr);
  const std::lock_guard lock(session_mutex);
  lazy_session = this;
  if (eager) initialize();
}

void PetscSession::initialize() {
  if (initialized_) return;
  // PT-Scotch (the cells' split over ranks) runs threads whose scheduling and its running random
  // generator make the parts of one graph differ between calls and runs; one thread (the ranks
  // take the cores anyway; a user's own setting is kept) makes them a function of the graph. Set
  // here, before MPI and PETSc start threads: setenv is unsafe beside a concurrent getenv.
  setenv("SCOTCH_PTHREAD_NUMBER", "1", 0);
  // A process that no launcher started is an MPI singleton: PMIx's default store (gds ds21) puts
  // its data in shared-memory files of several MB, so that under a file size limit (ulimit -f
  // below about 5 MB) MPI failed to start. Its hash store keeps them in memory.
  if (!launched_by_mpi_launcher()) setenv("PMIX_MCA_gds", "hash", 0);
  int argc = static_cast<int>(storage_.size());
  char** argv = argv_.data();
  if (SlepcInitialize(&argc, &argv, nullptr, nullptr) != 0) throw std::runtime_error("SlepcInitialize failed");
  initialized_ = true;
  // Every PETSc error comes back as a code that HPC_PETSC_CALL turns into an exception carrying
  // PETSc's message, on every rank. PETSc's default handler prints a traceback and, on a rank
  // other than 0, sleeps 10 s and then exits with status 0: a collective failure (every rank of a
  // BDDC or MUMPS solve) then looked like rank 0 failing alone, and the other ranks ended silently.
  // A user's -on_error_abort or -on_error_attach_debugger (for debugging) keeps PETSc's handler.
  PetscBool abort = PETSC_FALSE, debugger = PETSC_FALSE;
  PetscOptionsGetBool(nullptr, nullptr, "-on_error_abort", &abort, nullptr);  // (takes "false" too)
  PetscOptionsHasName(nullptr, nullptr, "-on_error_attach_debugger", &debugger);
  if (!abort && !debugger) errors_as_codes_ = PetscPushErrorHandler(PetscReturnErrorHandler, nullptr) == 0;
}

PetscSession::~PetscSession() {
  const std::lock_guard lock(session_mutex);
  lazy_session = nullptr;
  if (!initialized_) return;
  if (errors_as_codes_) PetscPopErrorHandler();  // (PETSc frees the handler's record)
  SlepcFinalize();
}

bool ensure_petsc_initialized() {
  PetscBool initialized = PETSC_FALSE;
  SlepcInitialized(&initialized);
  if (initialized == PETSC_TRUE) return true;
  const std::lock_guard lock(session_mutex);
  if (!lazy_session) return false;
  lazy_session->initialize();
  return true;
}

bool launched_by_mpi_launcher() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"})
    if (std::getenv(variable)) return true;
  return false;
}

int launcher_rank() {
  for (const char* variable : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
    if (const char* value = std::getenv(variable)) return std::atoi(value);
  return 0;
}

std::pair<int, int> mpi_rank_and_size() { return rank_and_size(MPI_COMM_WORLD); }

std::pair<int, int> rank_and_size(MPI_Comm ranks) {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (!initialized || finalized) return {0, 1};
  int rank = 0, size = 1;
  MPI_Comm_rank(ranks, &rank);
  MPI_Comm_size(ranks, &size);
  return {rank, size};
}

void sum_over_ranks(MPI_Comm ranks, double* data, std::size_t count) {
  if (rank_and_size(ranks).second == 1) return;
  // In chunks of 8 MB: Open MPI's allreduce of large messages allocates a temporary copy of the
  // message, which for a dense interface matrix (75 MB at 1e6 dofs on 4 ranks) was the largest
  // allocation of a rank; an int count also caps a single call at 2^31 entries.
  // A reduction on the first rank, then a broadcast of its bits: every rank holds the same sum
  // to the last bit (an allreduce may add in another order on each rank, and MPI does not
  // promise otherwise), so the decisions taken on replicated data (the contact solvers' active
  // sets, iteration counts, stopping tests) are the same on every rank.
  constexpr std::size_t chunk = std::size_t{1} << 20;
  const bool root = rank_and_size(ranks).first == 0;
  for (std::size_t first = 0; first < count; first += chunk) {
    const int n = static_cast<int>(std::min(chunk, count - first));
    double* piece = data + first;
    HPC_VERIFY(MPI_Reduce(root ? MPI_IN_PLACE : piece, root ? piece : nullptr, n, MPI_DOUBLE, MPI_SUM, 0, ranks) ==
                       MPI_SUCCESS &&
                   MPI_Bcast(piece, n, MPI_DOUBLE, 0, ranks) == MPI_SUCCESS,
               "summing over the ranks failed");
  }
}

}  // namespace hpcontact
