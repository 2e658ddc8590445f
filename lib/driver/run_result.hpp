// What a run of a scene computed, as types: one ContactResult per contact problem, the α of the
// pairing, the convergence rows, the operators built. summary.json, the printed report, the Python
// module and library programs all read these fields (summary_json.hpp writes the JSON from them).
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "contact/qp_report.hpp"
#include "core/operator_log.hpp"
#include "infsup/infsup_record.hpp"
#include "mesh/mesh.hpp"

namespace hpcontact::driver {

/// One zone of Γ_C in a contact result.
struct ZoneResult {
  double length = 0.0;                                 ///< arc length of the zone
  bool closed = false;                                 ///< a closed curve
  double contact_set_length = 0.0;                     ///< where the multiplier does not vanish, from the samples
  std::optional<double> total_force;                   ///< elastic: ∫ pressure ds over the zone
  std::optional<double> tangential_force;              ///< elastic: ∫ σ_nt ds over the zone
  std::optional<std::array<double, 2>> contact_force;  ///< elastic: ∫ (−p n + σ_nt t) ds over the zone
};

/// Constraint points of Remark 3 used per segment of T_{C,H}.
struct ConstraintPointCount {
  int min = 0, max = 0;
  long long total = 0;
};

/// Wall time of a contact solve's phases (seconds).
struct ContactSeconds {
  double assembly = 0.0, factorization = 0.0, condensation = 0.0, contact_qp = 0.0, recovery = 0.0;
  double total = 0.0;  ///< from the setup to the solution, as the run saw it
};

/// The contact pair a two-body problem was solved on: its name and its bodies.
struct PairSummary {
  std::string name, slave, master;
};

/// The solution against the scene's [exact] one: max |u_h − u| / max |u| over the body (both
/// bodies of a pair), max |p_h − p| / max |p| on Γ_C; each empty when not given.
struct ExactErrors {
  std::optional<double> displacement, pressure;
};

/// The multiplier outside its bounds between the points where they are imposed (λ ≤ 0, |λ| ≤ 1,
/// |λ| ≤ s; the elastic pressure ≥ 0), from the boundary samples.
struct MultiplierBounds {
  double violation = 0.0;  ///< the largest distance outside, relative to max |λ|
  mesh::Point at = mesh::Point::Zero();
  std::optional<double> to_free_boundary;  ///< arc length from there to the nearest end of the contact set
};

/// One contact problem solved on the scene's discretization.
struct ContactResult {
  std::string problem;  ///< the effect's name: signorini, friction, friction_s, frictionless, tresca, coulomb
  double energy = 0.0;  ///< E(u) = ½ a(u, u) − F(u)
  long long n_dofs = 0, nmult = 0, n_trace = 0;
  double contact_set_length = 0.0;
  /// (9) and elastic against a rigid obstacle (not tied): the contact set's half-width as a moment
  /// of the pressure (−λ for (9); postprocess/moment_half_width.hpp) — a on Hertz
  std::optional<double> moment_half_width;
  std::optional<double> contact_area;      ///< 3-D: the area of Γ_C where the multiplier does not vanish
  std::optional<double> total_force;       ///< elastic: P = ∫_{Γ_C} pressure ds
  std::optional<double> tangential_force;  ///< elastic: T = ∫_{Γ_C} σ_nt ds (along increasing s)
  /// elastic: the resultant of the contact traction on the body (the slave of a pair),
  /// ∫_{Γ_C} (−p n + σ_nt t) ds, in x and y
  std::optional<std::array<double, 2>> contact_force;
  std::vector<ZoneResult> zones;
  std::optional<ConstraintPointCount> constraint_points;  ///< scalar problems
  contact::QpReport solver;
  ContactSeconds seconds;
  std::vector<double> fixed_point_changes;     ///< Coulomb: max |Δλ| / max |λ| per fixed-point iteration
  std::optional<double> friction_coefficient;  ///< Coulomb
  std::optional<PairSummary> pair;             ///< two bodies: the pair (n_dofs counts both bodies)
  std::optional<ExactErrors> exact;            ///< the scene gives [exact]
  std::optional<MultiplierBounds> bounds;      ///< every problem with bounds (not tied)
};

/// The inf-sup constant of the scene's pairing (effect infsup).
struct InfSupSummary {
  /// α and its pairing: the record `hpcontact infsup --csv` and a sweep's alpha.csv write.
  infsup::InfSupRecord record;
  int reference_level = 0;                 ///< the H^{-1/2} reference's level behind alpha_error
  bool lambda_unique = true;               ///< α above round-off: λ is unique
  std::optional<std::string> primal_norm;  ///< elastic: h1 or energy
  double lambda_min = 0.0, lambda_max = 0.0;
  std::string eigensolver;
  double residual = 0.0;
  std::vector<double> zone_alpha;  ///< several zones: α of each zone's multipliers alone
};

/// One row of convergence.csv: a contact problem on one refinement level.
struct ConvergenceRow {
  std::string problem;
  int level = 0;
  long long p = 0, pc = 0;  ///< the largest degrees of the level
  long long n = 0, m = 0, n_dofs = 0, nmult = 0;
  double energy = 0.0, error_energy = 0.0, error_lambda = 0.0, seconds = 0.0;
  std::string p_rule, pc_rule;  ///< the degrees as the scene writes them (a number or a rule's text)
};

/// The material of an elastic scene, as written.
struct MaterialSummary {
  std::string model, young, poisson;
};

/// What the mesh was graded towards ([solve] fit_free_boundary).
struct FreeBoundarySummary {
  std::vector<mesh::Point> points;
  int rounds = 0;
  double moved = 0.0, seconds = 0.0;
};

/// One step of an adaptive run ([adapt]): the discretization solved, its estimate, what the step
/// then refined (adapt.csv, summary.json).
struct AdaptStep {
  int step = 0;
  long long unknowns = 0, multipliers = 0;
  double estimate = 0.0;  ///< η²/2, the estimated error in the energy
  double energy = 0.0;
  double alpha = 0.0;    ///< the predicted α of the step's pairing (NaN where the predictor failed)
  double seconds = 0.0;  ///< since the adaptivity began, this step's solve and estimate included
  int largest_degree = 0, deepest_level = 0;  ///< of T_h's cells
  int split = 0, raised = 0;                  ///< leaves split, degrees raised after the step
  /// The contact set's half-width as a moment of the pressure (−λ for (9);
  /// postprocess/moment_half_width.hpp): a on the Hertz problem; NaN for (13), (15) and tied contact.
  double moment_half_width = NAN;
};

/// An adaptive run's steps and why it stopped.
struct AdaptSummary {
  std::vector<AdaptStep> steps;
  std::string stopped;  ///< "target", "max_unknowns" or "max_steps"
  double target = 0.0;
  std::optional<double> reference_energy;  ///< adapt.reference_energy
};

/// A change of the scene that the predictor finds stable: the nearest to the scene's pairing
/// (the most multipliers among the stable candidates).
struct StableAlternative {
  std::string edit;  ///< the scene edit, e.g. `[discretization] pC = 2`
  double alpha_predicted = 0.0;
  long long nmult = 0;
};

/// The stability of the run's pairing as predicted before it is solved (infsup/local_alpha.hpp).
struct StabilityReport {
  double alpha_predicted = 0.0;  ///< min over the patches of Γ_C of the local α
  double threshold = 0.0;        ///< predicted stable iff alpha_predicted ≥ threshold
  bool stable = true;
  double pi = 0.0;            ///< Π(h, H, p, p_C) of (20) with θ = 1, largest over the segments
  mesh::Point weakest_point;  ///< the middle of the segment with the weakest patch
  int patches = 0, distinct_patches = 0;
  double seconds = 0.0;                          ///< the prediction and the search for an alternative
  std::optional<StableAlternative> alternative;  ///< when not stable and one was found
  std::string warning;                           ///< when not stable: the warning's text
  bool warned = false;                           ///< the run warned ([solve] stability = "warn")
  std::string failure;  ///< why there is no prediction (a patch's eigenproblem failed); then `stable`
};

struct RunResult {
  std::string scene;                 ///< the scene file
  std::vector<std::string> effects;  ///< as the scene lists them
  std::string p, pc;                 ///< the degrees as written
  std::string family;                ///< the multiplier family (space::to_string)
  std::optional<MaterialSummary> material;
  long long edges_on_contact = 0, m = 0, n_dofs = 0, nmult = 0;
  int dimension = 2;                          ///< 3 for a box of hexahedra
  std::optional<long long> faces_on_contact;  ///< 3-D: the trace faces on Γ_C (then m counts T_{C,H}'s cells)
  std::vector<OperatorRecord> operators;      ///< every operator built, in order
  std::optional<FreeBoundarySummary> free_boundary;
  std::optional<AdaptSummary> adapt;         ///< an adaptive scene: its steps (the effects ran on the last)
  std::optional<StabilityReport> stability;  ///< runs with a contact problem or α
  std::vector<ContactResult> contacts;       ///< in the order the problems ran
  std::optional<InfSupSummary> infsup;
  int convergence_refinements = 0;
  std::vector<ConvergenceRow> convergence;  ///< empty without the effect convergence
  double seconds_total = 0.0;
  int ranks = 1;
  std::string distributed_solver;

  /// The result of the contact problem named `problem`. @throws std::out_of_range if it did not run.
  const ContactResult& contact(const std::string& problem) const;
};

}  // namespace hpcontact::driver
