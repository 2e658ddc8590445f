// PrimalOperators: lazy members, each logged once. The trace dofs are the columns a full-degree
// multiplier space on the edges of T_h|Γ_C touches (Legendre polynomials up to p span every trace
// function's restriction to an edge).
#include "operators/primal_operators.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "mesh/boundary_mesh.hpp"
#include "operators/rank_space.hpp"

namespace hpcontact::operators {

PrimalOperators::PrimalOperators(const mesh::Mesh* mesh, std::vector<int> cell_degrees, OperatorLog* log,
                                 linalg::Distribution distribution)
    : whole_(mesh, cell_degrees, distribution), log_(log), distribution_(distribution) {
  Stopwatch clock;
  rank_ = build_rank_space(mesh, std::move(cell_degrees), distribution);
  // Γ_C of the space's mesh: the whole one, or the part (which holds all of Γ_C's cells).
  contact_ = std::make_unique<mesh::ContactBoundary>(rank_.space->mesh());
  if (log_) log_->record("S^p(T_h)", rank_.space->n_dofs(), 0, clock.seconds());
}

PrimalOperators::PrimalOperators(const mesh::Mesh& mesh, std::vector<int> cell_degrees, OperatorLog* log,
                                 linalg::Distribution distribution)
    : PrimalOperators(&mesh, std::move(cell_degrees), log, distribution) {}

PrimalOperators::~PrimalOperators() = default;

bool PrimalOperators::built_on(const mesh::Mesh& mesh, const std::vector<int>& cell_degrees) const {
  return space_built_on(*rank_.space, whole_, mesh, cell_degrees);
}

const std::vector<int>& PrimalOperators::trace_dofs() const {
  if (!trace_dofs_) {
    // The whole space's largest degree, on every rank alike (a part's own can be lower): every rank
    // must find the same trailing set.
    const int p_max = rank_.space->max_degree();
    const mesh::BoundaryMesh edges = contact_->edge_mesh();  // full_trace keeps a pointer to it
    const space::MultiplierSpace full_trace(edges, p_max);
    trace_dofs_ = std::make_unique<std::vector<int>>(
        linalg::nonzero_columns(assembly::assemble_coupling(*rank_.space, *contact_, full_trace)));
  }
  return *trace_dofs_;
}

namespace {

// Factorizes stiffness_weight K + mass_weight M into `slot` on first use and logs it as `name`.
const assembly::CondensedFactor& condensed_factor(const space::H1Space& space, double stiffness_weight,
                                                  double mass_weight, const std::vector<int>& trace,
                                                  linalg::Distribution distribution,
                                                  const std::vector<int>& part_of_cell,
                                                  std::unique_ptr<assembly::CondensedFactor>& slot, const char* name,
                                                  OperatorLog* log) {
  if (!slot) {
    Stopwatch clock;
    slot = std::make_unique<assembly::CondensedFactor>(space, stiffness_weight, mass_weight, trace, distribution,
                                                       part_of_cell);
    if (log) log->record(name, slot->size(), slot->size(), clock.seconds());
  }
  return *slot;
}

}  // namespace

const assembly::CondensedFactor& PrimalOperators::stiffness_factor() const {
  // Without Dirichlet edges K has the constants in its kernel: refuse as input, not as a failed
  // factorization deep inside CHOLMOD.
  if (!whole_.has_dirichlet())
    throw InputError(
        "the body has no Dirichlet part (no boundary edge is in Γ_D: key 'boundary.dirichlet' or "
        "'boundary.dirichlet_groups'): K is singular, since u + c has the energy of u, and the contact "
        "problems (9), (13), (15) need u fixed somewhere (the inf-sup analysis, with K + M, does not)");
  return condensed_factor(*rank_.space, 1.0, 0.0, trace_dofs(), distribution_, rank_.cell_parts, stiffness_factor_,
                          "factor(K)", log_);
}

const assembly::CondensedFactor& PrimalOperators::gram_factor(TraceOrdering ordering) const {
  static const std::vector<int> anywhere;
  return condensed_factor(*rank_.space, 1.0, 1.0, ordering == TraceOrdering::last ? trace_dofs() : anywhere,
                          distribution_, rank_.cell_parts, gram_factor_, "factor(K+M)", log_);
}

void PrimalOperators::release_factors() const {
  assembly::log_iterations(stiffness_factor_.get(), "factor(K)", log_);
  assembly::log_iterations(gram_factor_.get(), "factor(K+M)", log_);
  stiffness_factor_.reset();
  gram_factor_.reset();
}

const linalg::Coupling& PrimalOperators::coupling(const space::MultiplierSpace& multipliers,
                                                  const assembly::CouplingWeight& weight,
                                                  const std::string& name) const {
  const std::string key = coupling_key(multipliers, name, weight);
  auto found = couplings_.find(key);
  if (found == couplings_.end()) {
    Stopwatch clock;
    found =
        couplings_.emplace(key, assembly::assemble_coupling(*rank_.space, *contact_, multipliers, weight.function()))
            .first;
    if (weight) weights_.push_back(weight);
    if (log_) log_->record(name, found->second.rows(), found->second.cols(), clock.seconds());
  }
  return found->second;
}

std::string PrimalOperators::coupling_key(const space::MultiplierSpace& multipliers, const std::string& name,
                                          const assembly::CouplingWeight& weight) {
  // The layout of the multiplier space identifies it: its segments and their degrees.
  std::string key = weight ? fmt::format("{}[{}]", name, weight.identity()) : name;
  for (int k = 0; k < multipliers.n_segments(); ++k)
    key += fmt::format("|{:.17g}:{}", multipliers.boundary_mesh().segment_end(k), multipliers.segment_degree(k));
  return key;
}

namespace {

template <class Value>
const Value& memoized(std::map<std::string, Value>& slots, const std::string& name, const std::string& key,
                      const std::function<Value()>& build, OperatorLog* log) {
  auto found = slots.find(key);
  if (found == slots.end()) {
    Stopwatch clock;
    found = slots.emplace(key, build()).first;
    if (log) log->record(name, found->second.rows(), found->second.cols(), clock.seconds());
  }
  return found->second;
}

}  // namespace

const Eigen::VectorXd& PrimalOperators::derived_vector(const std::string& name, const std::string& key,
                                                       const std::function<Eigen::VectorXd()>& build) const {
  return memoized(derived_vectors_, name, name + "#" + key, build, log_);
}

const Eigen::MatrixXd& PrimalOperators::derived_matrix(const std::string& name, const std::string& key,
                                                       const std::function<Eigen::MatrixXd()>& build) const {
  return memoized(derived_matrices_, name, name + "#" + key, build, log_);
}

const PrimalOperators& shared_or_own(const PrimalOperators* shared, const mesh::Mesh* mesh,
                                     const std::vector<int>& cell_degrees, std::unique_ptr<PrimalOperators>& own) {
  HPC_VERIFY(shared || mesh, "neither shared primal operators nor a mesh to build them on");
  if (!shared) {
    own = std::make_unique<PrimalOperators>(*mesh, cell_degrees);
    return *own;
  }
  HPC_VERIFY(!mesh || shared->built_on(*mesh, cell_degrees),
             "shared primal operators of another mesh or degree distribution");
  return *shared;
}

}  // namespace hpcontact::operators
