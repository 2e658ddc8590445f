// Checking PETSc/SLEPc options on the command line before any work: unprefixed names (with the
// prefixed one suggested), values SLEPc rejects, and names no setter reads.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <slepceps.h>

#include <cctype>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/petsc_check.hpp"
#include "infsup/generalized_eigen.hpp"

namespace hpcontact::infsup {

void check_petsc_options(const std::vector<std::string>& arguments, const std::string& options_prefix) {
  const std::string prefixed = "-" + options_prefix;
  std::vector<std::string> names;
  for (std::size_t k = 1; k < arguments.size(); ++k) {
    const std::string& name = arguments[k];
    if (name.empty() || name[0] != '-' || std::isdigit(static_cast<unsigned char>(name.size() > 1 ? name[1] : '0')))
      continue;  // a value
    bool global = false;
    for (const char* allowed : {"-help", "-info", "-log_", "-options_left", "-malloc", "-on_error_", "-mat_mumps_",
                                "-no_signal_handler", "-bddc_", "-gamg_"})
      global = global || name.rfind(allowed, 0) == 0;
    if (global) continue;
    if (name.rfind(prefixed, 0) != 0)
      throw_bad_input("command line", "PETSc option", name,
                      fmt::format("not read by hpcontact: the inf-sup eigensolver reads its options with the prefix "
                                  "{}, the distributed solvers bddc and gamg with bddc_ and gamg_ (did you mean {}{}?)",
                                  options_prefix, prefixed, name.substr(1)));
    names.push_back(name);
  }
  if (names.empty()) return;
  // Both eigensolvers' objects read their options; PETSc reports a bad value as an error, which
  // must not print PETSc's traceback here.
  HPC_PETSC_CALL(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  std::string bad;
  // (the products' EPS is a Generalized Davidson, whose own options only a GD reads: infsup/products_eigen.hpp)
  for (const std::string& extra : {std::string(), std::string("max_"), std::string("products_")}) {
    EPS eps = nullptr;
    PetscErrorCode code = EPSCreate(PETSC_COMM_SELF, &eps);
    if (!code && extra == "products_") code = EPSSetType(eps, EPSGD);
    if (!code) code = EPSSetOptionsPrefix(eps, (options_prefix + extra).c_str());
    if (!code) code = EPSSetFromOptions(eps);
    if (code && bad.empty()) {
      const char* text = nullptr;
      PetscErrorMessage(code, &text, nullptr);
      bad = text ? text : "rejected by SLEPc";
    }
    if (eps) EPSDestroy(&eps);
  }
  PetscPopErrorHandler();
  if (!bad.empty())
    throw_bad_input(
        "command line", "PETSc options", fmt::format("{}", fmt::join(arguments.begin() + 1, arguments.end(), " ")),
        "SLEPc rejects a value (" + bad + "); see -" + options_prefix + "eps_view and -help for the choices");
  // A name that no setter queried is misspelled (views and monitors are read later, when solving).
  for (const std::string& name : names) {
    if (name.find("view") != std::string::npos || name.find("monitor") != std::string::npos) continue;
    PetscBool used = PETSC_FALSE;
    HPC_PETSC_CALL(PetscOptionsUsed(nullptr, name.c_str() + 1, &used));  // stored without the dash
    if (!used)
      throw_bad_input("command line", "PETSc option", name,
                      "not an option of the inf-sup eigensolver (SLEPc EPS with ST, KSP, PC): see -" + options_prefix +
                          "eps_view and -help for the names");
  }
}

}  // namespace hpcontact::infsup
