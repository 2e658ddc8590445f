// solve_elastic_contact: the body against the rigid obstacle on the condensed trace solver
// (elastic_trace_solver.hpp).
#include "contact/elastic_contact.hpp"

#include "assembly/coupling.hpp"
#include "contact/elastic_trace_solver.hpp"
#include "core/error.hpp"

namespace hpcontact::contact {

std::string to_string(ElasticContactProblem problem) {
  switch (problem) {
    case ElasticContactProblem::frictionless:
      return "frictionless";
    case ElasticContactProblem::tresca:
      return "tresca";
    case ElasticContactProblem::coulomb:
      return "coulomb";
    case ElasticContactProblem::tied:
      return "tied";
  }
  return "?";
}

ElasticContactSolution solve_elastic_contact(const ElasticContactSetup& setup) {
  HPC_VERIFY(setup.operators && setup.boundary_mesh, "elastic contact setup without operators or T_{C,H}");
  if (!setup.gap) throw InputError("elastic contact: the gap g to the obstacle is missing");
  const auto& contact = setup.operators->contact();
  return solve_on_trace(setup, [&](double s) { return setup.gap(contact.point_at(s)); }, {body_on_own_traces(setup)})
      .contact;
}

}  // namespace hpcontact::contact
