// summary.json written from RunResult.
#include "driver/summary_json.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

namespace hpcontact::driver {
namespace {

using nlohmann::json;

json solver_json(const contact::QpReport& qp) {
  json j{{"method", qp.method},         {"converged", qp.converged},           {"kkt_residual", qp.kkt_residual},
         {"iterations", qp.iterations}, {"proximal_steps", qp.proximal_steps}, {"trace_operator", qp.trace_operator}};
  if (qp.trace_operator == "products") j["products"] = qp.products;
  if (qp.trace_operator == "saddle_point") {
    j["cg_iterations"] = qp.products;
    j["preconditioner_applications"] = qp.preconditioner_applications;
  }
  if (!qp.fallback_reason.empty()) j["fallback_reason"] = qp.fallback_reason;
  for (const auto& step : qp.log)
    j["log"].push_back({{"iteration", step.iteration},
                        {"active_set_changes", step.active_set_changes},
                        {"kkt_residual", step.kkt_residual}});
  return j;
}

json contact_json(const ContactResult& c) {
  json j{{"energy", c.energy},
         {"nmult", c.nmult},
         {"n_trace", c.n_trace},
         {"solver", solver_json(c.solver)},
         {"seconds",
          {{"assembly", c.seconds.assembly},
           {"factorization", c.seconds.factorization},
           {"condensation", c.seconds.condensation},
           {"contact_qp", c.seconds.contact_qp},
           {"recovery", c.seconds.recovery},
           {"total", c.seconds.total}}}};
  if (c.contact_area)
    j["contact_area"] = *c.contact_area;
  else
    j["contact_set_length"] = c.contact_set_length;
  if (c.moment_half_width) j["moment_half_width"] = *c.moment_half_width;
  if (c.total_force) j["total_force"] = *c.total_force;
  if (c.tangential_force) j["tangential_force"] = *c.tangential_force;
  if (c.contact_force) j["contact_force"] = *c.contact_force;
  j["zones"] = json::array();
  for (const auto& zone : c.zones) {
    j["zones"].push_back(
        {{"length", zone.length}, {"closed", zone.closed}, {"contact_set_length", zone.contact_set_length}});
    if (zone.total_force) j["zones"].back()["total_force"] = *zone.total_force;
    if (zone.tangential_force) j["zones"].back()["tangential_force"] = *zone.tangential_force;
    if (zone.contact_force) j["zones"].back()["contact_force"] = *zone.contact_force;
  }
  if (c.constraint_points)
    j["constraint_points_per_segment"] = {
        {"min", c.constraint_points->min}, {"max", c.constraint_points->max}, {"total", c.constraint_points->total}};
  if (!c.fixed_point_changes.empty())
    j["fixed_point"] = {{"iterations", c.fixed_point_changes.size()}, {"changes", c.fixed_point_changes}};
  if (c.friction_coefficient) j["friction_coefficient"] = *c.friction_coefficient;
  if (c.exact) {
    j["exact_errors"] = json::object();
    if (c.exact->displacement) j["exact_errors"]["displacement"] = *c.exact->displacement;
    if (c.exact->pressure) j["exact_errors"]["pressure"] = *c.exact->pressure;
  }
  if (c.bounds) {
    j["multiplier_bounds"] = {{"violation", c.bounds->violation}, {"at", {c.bounds->at.x(), c.bounds->at.y()}}};
    if (c.bounds->to_free_boundary) j["multiplier_bounds"]["distance_to_free_boundary"] = *c.bounds->to_free_boundary;
  }
  if (c.pair) j["pair"] = {{"name", c.pair->name}, {"slave", c.pair->slave}, {"master", c.pair->master}};
  return j;
}

json stability_json(const StabilityReport& s) {
  json j = {{"alpha_predicted", s.alpha_predicted},
            {"threshold", s.threshold},
            {"stable", s.stable},
            {"pi", s.pi},
            {"weakest_point", {s.weakest_point.x(), s.weakest_point.y()}},
            {"patches", s.patches},
            {"distinct_patches", s.distinct_patches},
            {"seconds", s.seconds}};
  if (s.alternative)
    j["alternative"] = {{"edit", s.alternative->edit},
                        {"alpha_predicted", s.alternative->alpha_predicted},
                        {"nmult", s.alternative->nmult}};
  if (!s.warning.empty()) j["warning"] = s.warning;
  j["warned"] = s.warned;
  if (!s.failure.empty()) j["failure"] = s.failure;
  return j;
}

json infsup_json(const InfSupSummary& a) {
  const auto& r = a.record;
  json j{{"alpha", r.alpha},
         {"alpha_error", r.alpha_error},
         {"alpha_converged", r.alpha_converged.value_or(true)},
         {"reference_level", a.reference_level},
         {"lambda_unique", a.lambda_unique},
         {"problem", infsup::to_string(r.problem)},
         {"norm", infsup::to_string(r.norm)},
         {"lambda_min", a.lambda_min},
         {"lambda_max", a.lambda_max},
         {"Pi", r.pi},
         {"eigensolver", a.eigensolver},
         {"residual", a.residual},
         {"seconds", r.seconds}};
  if (a.primal_norm) j["primal_norm"] = *a.primal_norm;
  if (!a.zone_alpha.empty()) j["zone_alpha"] = a.zone_alpha;
  return j;
}

json operators_json(const std::vector<OperatorRecord>& records) {
  json operators = json::array();
  for (const auto& record : records) {
    operators.push_back(
        {{"name", record.name}, {"rows", record.rows}, {"cols", record.cols}, {"seconds", record.seconds}});
    if (record.solves > 0)
      operators.back()["iterations"] = {
          {"solves", record.solves}, {"total", record.iterations}, {"most", record.most_iterations}};
  }
  return operators;
}

}  // namespace

std::string summary_json(const RunResult& r) {
  json j{{"scene", r.scene},
         {"effects", r.effects},
         {"p", r.p},
         {"pC", r.pc},
         {"family", r.family},
         {"dimension", r.dimension},
         {"m", r.m},
         {"ndofs", r.n_dofs},
         {"nmult", r.nmult},
         {"operators", operators_json(r.operators)},
         {"seconds_total", r.seconds_total},
         {"ranks", r.ranks},
         {"distributed_solver", r.distributed_solver}};
  if (r.faces_on_contact)
    j["faces_on_contact"] = *r.faces_on_contact;
  else
    j["edges_on_contact"] = r.edges_on_contact;
  if (r.material) j["material"] = {{"model", r.material->model}, {"E", r.material->young}, {"nu", r.material->poisson}};
  if (r.free_boundary) {
    json points = json::array();
    for (const auto& point : r.free_boundary->points) points.push_back({point.x(), point.y()});
    j["free_boundary"] = {{"points", points},
                          {"rounds", r.free_boundary->rounds},
                          {"moved", r.free_boundary->moved},
                          {"seconds", r.free_boundary->seconds}};
  }
  if (r.adapt) {
    const auto& last = r.adapt->steps.back();
    j["adapt"] = {{"steps", r.adapt->steps.size()},   {"stopped", r.adapt->stopped},
                  {"target", r.adapt->target},        {"estimate", last.estimate},
                  {"largest_p", last.largest_degree}, {"deepest_level", last.deepest_level},
                  {"seconds", last.seconds},          {"file", "adapt.csv"}};
    if (!std::isnan(last.moment_half_width)) j["adapt"]["moment_half_width"] = last.moment_half_width;
  }
  if (r.stability) j["stability"] = stability_json(*r.stability);
  for (const auto& contact : r.contacts) j[contact.problem] = contact_json(contact);
  if (r.infsup) j["infsup"] = infsup_json(*r.infsup);
  if (!r.convergence.empty())
    j["convergence"] = {{"refinements", r.convergence_refinements}, {"file", "convergence.csv"}};
  return j.dump(2) + "\n";
}

}  // namespace hpcontact::driver
