// HPC_PETSC_CALL: checks the error code of a PETSc/SLEPc call and throws NumericalError carrying
// PETSc's own message; ScopedPetscErrorsAsCodes keeps PETSc from printing its traceback meanwhile.
#pragma once

#include <petscsys.h>

#include <string>

#include "core/error.hpp"
#include "core/memory_limit.hpp"

namespace hpcontact::detail {

/// Throws NumericalError naming the failed expression, PETSc's text for `code` and the specific
/// message of the error as first raised (e.g. "Zero pivot in row 3").
[[noreturn]] inline void throw_petsc_error(PetscErrorCode code, const char* expression, const char* file, int line) {
  const char* generic = nullptr;
  char* specific = nullptr;
  PetscErrorMessage(code, &generic, &specific);
  std::string message = std::string("PETSc error ") + std::to_string(static_cast<int>(code)) + " in '" + expression +
                        "' (" + file + ":" + std::to_string(line) + ")";
  if (generic != nullptr) message += ": " + std::string(generic);
  if (specific != nullptr && specific[0] != '\0') message += ": " + std::string(specific);
  if (code == PETSC_ERR_MEM) throw OutOfMemory(out_of_memory_message("in a PETSc call") + " (" + message + ")");
  throw NumericalError(message);
}

}  // namespace hpcontact::detail

/// Evaluates a PETSc/SLEPc call once; a non-zero error code throws hpcontact::NumericalError.
#define HPC_PETSC_CALL(expr)                                                                                      \
  do {                                                                                                            \
    const PetscErrorCode hpc_petsc_code_ = (expr);                                                                \
    if (hpc_petsc_code_ != 0) ::hpcontact::detail::throw_petsc_error(hpc_petsc_code_, #expr, __FILE__, __LINE__); \
  } while (false)

namespace hpcontact {

/// RAII: while alive, PETSc errors are returned as codes without printing a traceback to
/// stderr (PetscReturnErrorHandler); HPC_PETSC_CALL turns them into exceptions whose message
/// already holds PETSc's text. The previous handler is restored on destruction. (PetscSession
/// installs the same handler for the whole process; this keeps a caller that initialized PETSc
/// itself from PETSc's default handler, which ends ranks other than 0 with exit status 0.)
class ScopedPetscErrorsAsCodes {
 public:
  ScopedPetscErrorsAsCodes() { HPC_PETSC_CALL(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr)); }
  ~ScopedPetscErrorsAsCodes() { PetscPopErrorHandler(); }
  ScopedPetscErrorsAsCodes(const ScopedPetscErrorsAsCodes&) = delete;
  ScopedPetscErrorsAsCodes& operator=(const ScopedPetscErrorsAsCodes&) = delete;
};

}  // namespace hpcontact
