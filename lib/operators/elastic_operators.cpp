// ElasticOperators: lazy members, each logged once.
#include "operators/elastic_operators.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/timer.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "mesh/boundary_mesh.hpp"
#include "operators/primal_operators.hpp"
#include "operators/rank_space.hpp"

namespace hpcontact::operators {

std::string to_string(PrimalNorm norm) { return norm == PrimalNorm::h1 ? "h1" : "energy"; }

ElasticOperators::ElasticOperators(const mesh::Mesh* mesh, std::vector<int> cell_degrees,
                                   std::vector<assembly::Material> materials, OperatorLog* log,
                                   const std::array<std::vector<char>, space::kComponents>& fixed,
                                   linalg::Distribution distribution)
    : whole_(mesh, cell_degrees, distribution), log_(log), distribution_(distribution) {
  Stopwatch clock;
  HPC_VERIFY(mesh || distribution.distributed(), "a serial space without a mesh");
  // (distributed, build_rank_space checks them on the first rank, which every rank then hears of)
  if (!distribution.distributed() && static_cast<int>(materials.size()) != mesh->n_cells())
    throw InputError("elasticity: one material per cell is needed");
  rotation_centre_ = whole_.vertex_mean();
  rank_ = build_rank_space(mesh, std::move(cell_degrees), distribution, &fixed,
                           distribution.distributed() ? &materials : nullptr);
  // Distributed: the materials of the part's cells.
  materials_ = distribution.distributed() ? std::move(rank_.materials) : std::move(materials);
  // Γ_C of the space's mesh: the whole one, or the part (which holds all of Γ_C's cells).
  contact_ = std::make_unique<mesh::ContactBoundary>(rank_.space->mesh());
  if (log_) log_->record("[S^p(T_h)]^2", n_dofs(), 0, clock.seconds());
}

ElasticOperators::ElasticOperators(const mesh::Mesh& mesh, std::vector<int> cell_degrees,
                                   std::vector<assembly::Material> materials, OperatorLog* log,
                                   const std::array<std::vector<char>, space::kComponents>& fixed,
                                   linalg::Distribution distribution)
    : ElasticOperators(&mesh, std::move(cell_degrees), std::move(materials), log, fixed, distribution) {}

ElasticOperators::~ElasticOperators() = default;

bool ElasticOperators::built_on(const mesh::Mesh& mesh, const std::vector<int>& cell_degrees) const {
  return space_built_on(*rank_.space, whole_, mesh, cell_degrees);
}

const std::vector<int>& ElasticOperators::trace_dofs() const {
  if (!trace_dofs_) {
    // The scalar trace dofs (columns a full-degree multiplier space on the edges of T_h|Γ_C
    // touches), each with both components.
    // The whole space's largest degree, on every rank alike (a part's own can be lower): every rank
    // must find the same trailing set.
    const int p_max = rank_.space->max_degree();
    const mesh::BoundaryMesh edges = contact_->edge_mesh();  // full_trace keeps a pointer to it
    const space::MultiplierSpace full_trace(edges, p_max);
    const auto scalar = linalg::nonzero_columns(assembly::assemble_coupling(*rank_.space, *contact_, full_trace));
    trace_dofs_ = std::make_unique<std::vector<int>>();
    for (int dof : scalar)
      for (int c = 0; c < space::kComponents; ++c)
        if (const int k = rank_.vector_space->dof(dof, c); k >= 0) trace_dofs_->push_back(k);
  }
  return *trace_dofs_;
}

namespace {

std::string gram_factor_name(PrimalNorm norm) { return norm == PrimalNorm::h1 ? "factor(K+M)^2" : "factor(A+M)"; }

}  // namespace

const assembly::CondensedFactor& ElasticOperators::stiffness_factor() const {
  if (!stiffness_factor_) {
    if (!whole_.has_dirichlet() && !rank_.vector_space->has_rollers())
      throw InputError(
          "the body has no Dirichlet part (no boundary edge is in Γ_D: key 'boundary.dirichlet' or "
          "'boundary.dirichlet_groups', and no roller: 'boundary.fixed_x', 'boundary.fixed_y'): the elasticity "
          "operator is singular, since rigid motions have no energy, and the contact problems need the body held "
          "somewhere");
    Stopwatch clock;
    stiffness_factor_ = std::make_unique<assembly::CondensedFactor>(
        std::make_unique<assembly::ElasticCellSystem>(*rank_.vector_space, materials_, 0.0, rotation_centre_),
        trace_dofs(), distribution_, rank_.cell_parts);
    if (log_) log_->record("factor(A)", n_dofs(), n_dofs(), clock.seconds());
  }
  return *stiffness_factor_;
}

void ElasticOperators::release_factors() const {
  assembly::log_iterations(stiffness_factor_.get(), "factor(A)", log_);
  for (const auto& [norm, factor] : gram_factors_) assembly::log_iterations(factor.get(), gram_factor_name(norm), log_);
  stiffness_factor_.reset();
  gram_factors_.clear();
}

const assembly::CondensedFactor& ElasticOperators::gram_factor(PrimalNorm norm) const {
  auto& slot = gram_factors_[norm];
  if (!slot) {
    Stopwatch clock;
    std::unique_ptr<const assembly::CellSystem> system;
    if (norm == PrimalNorm::h1)
      system = std::make_unique<assembly::ComponentwiseCellSystem>(*rank_.vector_space, 1.0, 1.0);
    else
      system = std::make_unique<assembly::ElasticCellSystem>(*rank_.vector_space, materials_, 1.0, rotation_centre_);
    slot =
        std::make_unique<assembly::CondensedFactor>(std::move(system), trace_dofs(), distribution_, rank_.cell_parts);
    if (log_) log_->record(gram_factor_name(norm), n_dofs(), n_dofs(), clock.seconds());
  }
  return *slot;
}

const linalg::Coupling& ElasticOperators::coupling(const space::MultiplierSpace& multipliers,
                                                   assembly::TraceDirection direction) const {
  const std::string name = direction == assembly::TraceDirection::normal ? "B_n" : "B_t";
  const std::string key = PrimalOperators::coupling_key(multipliers, name);
  auto found = couplings_.find(key);
  if (found == couplings_.end()) {
    Stopwatch clock;
    found = couplings_
                .emplace(key, assembly::assemble_directional_coupling(*rank_.vector_space, *contact_, multipliers,
                                                                      direction))
                .first;
    if (log_) log_->record(name, found->second.rows(), found->second.cols(), clock.seconds());
  }
  return found->second;
}

}  // namespace hpcontact::operators
