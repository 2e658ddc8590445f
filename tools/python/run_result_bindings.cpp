// Python classes for driver::RunResult, ContactResult, InfSupSummary, ConvergenceRow, QpReport.
#include "run_result_bindings.hpp"

#include <pybind11/stl.h>

#include "driver/run_result.hpp"

namespace py = pybind11;

namespace hpcontact::python {

namespace {

// One contact problem's result: its solver report and its zones.
void bind_contact_result(py::module_& m) {
  using driver::ContactResult, driver::ZoneResult;
  py::class_<contact::QpReport>(m, "SolverReport", "How the contact QP was solved")
      .def_readonly("method", &contact::QpReport::method)
      .def_readonly("converged", &contact::QpReport::converged)
      .def_readonly("kkt_residual", &contact::QpReport::kkt_residual)
      .def_readonly("iterations", &contact::QpReport::iterations)
      .def_readonly("proximal_steps", &contact::QpReport::proximal_steps)
      .def_readonly("trace_operator", &contact::QpReport::trace_operator)
      .def_readonly("products", &contact::QpReport::products);
  py::class_<ZoneResult>(m, "ZoneResult", "One zone of Γ_C in a contact result")
      .def_readonly("length", &ZoneResult::length)
      .def_readonly("closed", &ZoneResult::closed)
      .def_readonly("contact_set_length", &ZoneResult::contact_set_length)
      .def_readonly("total_force", &ZoneResult::total_force)
      .def_readonly("tangential_force", &ZoneResult::tangential_force)
      .def_readonly("contact_force", &ZoneResult::contact_force);
  py::class_<ContactResult>(m, "ContactResult", "One contact problem solved")
      .def_readonly("problem", &ContactResult::problem)
      .def_readonly("energy", &ContactResult::energy)
      .def_readonly("n_dofs", &ContactResult::n_dofs)
      .def_readonly("nmult", &ContactResult::nmult)
      .def_readonly("contact_set_length", &ContactResult::contact_set_length)
      .def_readonly("contact_area", &ContactResult::contact_area)
      .def_readonly("total_force", &ContactResult::total_force)
      .def_readonly("tangential_force", &ContactResult::tangential_force)
      .def_readonly("contact_force", &ContactResult::contact_force)
      .def_readonly("zones", &ContactResult::zones)
      .def_readonly("solver", &ContactResult::solver)
      .def_readonly("fixed_point_changes", &ContactResult::fixed_point_changes)
      .def("__repr__", [](const ContactResult& c) {
        return "<hpcontact.ContactResult " + c.problem + " energy=" + std::to_string(c.energy) + ">";
      });
}

}  // namespace

void bind_run_result(py::module_& m) {
  using driver::InfSupSummary, driver::RunResult;
  bind_contact_result(m);
  // α's pairing and value live in the summary's InfSupRecord; Python reads them as attributes.
  py::class_<InfSupSummary>(m, "InfSupSummary", "The inf-sup constant of the scene's pairing")
      .def_property_readonly("alpha", [](const InfSupSummary& a) { return a.record.alpha; })
      .def_property_readonly("alpha_error", [](const InfSupSummary& a) { return a.record.alpha_error; })
      .def_property_readonly("alpha_converged",
                             [](const InfSupSummary& a) { return a.record.alpha_converged.value_or(true); })
      .def_readonly("lambda_unique", &InfSupSummary::lambda_unique)
      .def_property_readonly("problem", [](const InfSupSummary& a) { return infsup::to_string(a.record.problem); })
      .def_property_readonly("norm", [](const InfSupSummary& a) { return infsup::to_string(a.record.norm); })
      .def_property_readonly("pi", [](const InfSupSummary& a) { return a.record.pi; })
      .def_property_readonly("p", [](const InfSupSummary& a) { return a.record.p; })
      .def_property_readonly("pc", [](const InfSupSummary& a) { return a.record.pc; })
      .def_property_readonly("family", [](const InfSupSummary& a) { return space::to_string(a.record.family); })
      .def_property_readonly("h", [](const InfSupSummary& a) { return a.record.h; })
      .def_property_readonly("H", [](const InfSupSummary& a) { return a.record.H; })
      .def_readonly("zone_alpha", &InfSupSummary::zone_alpha);
  py::class_<driver::StableAlternative>(m, "StableAlternative", "A scene edit the predictor finds stable")
      .def_readonly("edit", &driver::StableAlternative::edit)
      .def_readonly("alpha_predicted", &driver::StableAlternative::alpha_predicted)
      .def_readonly("nmult", &driver::StableAlternative::nmult);
  py::class_<driver::StabilityReport>(m, "StabilityReport", "The pairing's stability as predicted before the solve")
      .def_readonly("alpha_predicted", &driver::StabilityReport::alpha_predicted)
      .def_readonly("threshold", &driver::StabilityReport::threshold)
      .def_readonly("stable", &driver::StabilityReport::stable)
      .def_readonly("pi", &driver::StabilityReport::pi)
      .def_property_readonly("weakest_point",
                             [](const driver::StabilityReport& s) {
                               return std::array<double, 2>{s.weakest_point.x(), s.weakest_point.y()};
                             })
      .def_readonly("patches", &driver::StabilityReport::patches)
      .def_readonly("distinct_patches", &driver::StabilityReport::distinct_patches)
      .def_readonly("failure", &driver::StabilityReport::failure)
      .def_readonly("alternative", &driver::StabilityReport::alternative)
      .def_readonly("warning", &driver::StabilityReport::warning)
      .def_readonly("warned", &driver::StabilityReport::warned)
      .def_readonly("seconds", &driver::StabilityReport::seconds);
  py::class_<RunResult>(m, "RunResult", "What a scene run computed")
      .def_readonly("scene", &RunResult::scene)
      .def_readonly("effects", &RunResult::effects)
      .def_readonly("p", &RunResult::p)
      .def_readonly("pC", &RunResult::pc)
      .def_readonly("family", &RunResult::family)
      .def_readonly("m", &RunResult::m)
      .def_readonly("dimension", &RunResult::dimension)
      .def_readonly("faces_on_contact", &RunResult::faces_on_contact)
      .def_readonly("n_dofs", &RunResult::n_dofs)
      .def_readonly("nmult", &RunResult::nmult)
      .def_readonly("contacts", &RunResult::contacts)
      .def_readonly("infsup", &RunResult::infsup)
      .def_readonly("stability", &RunResult::stability)
      .def_readonly("seconds_total", &RunResult::seconds_total)
      .def("contact", &RunResult::contact, py::arg("problem"), py::return_value_policy::reference_internal,
           "The result of the contact problem named `problem` (IndexError if it did not run)");
}

}  // namespace hpcontact::python
