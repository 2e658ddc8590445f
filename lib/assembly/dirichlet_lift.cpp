// DirichletLift: the projection-based interpolant of u_D on the fixed edges, and its action.
#include "assembly/dirichlet_lift.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "assembly/cell_values.hpp"
#include "basis/lobatto.hpp"
#include "basis/quadrature.hpp"
#include "core/error.hpp"
#include "core/petsc_session.hpp"
#include "mesh/cell_map.hpp"

namespace hpcontact::assembly {

Eigen::VectorXd edge_projection(const mesh::Mesh& mesh, int cell, int local_edge, int degree, const PointFunction& u) {
  Eigen::VectorXd a = Eigen::VectorXd::Zero(std::max(degree - 1, 0));
  if (degree < 2) return a;
  const mesh::CellMap map(mesh, cell);
  auto at = [&](double t) {
    const Eigen::Vector2d ref = mesh::local_edge_point(map.type(), local_edge, t);
    return u(map.map(ref.x(), ref.y()));
  };
  const double start = at(-1.0), end = at(1.0);
  // a_k = ∫ g' N_k' = −∫ g N_k'' with g = u − I₁u vanishing at ±1, N_k'' = √((2k−1)/2) P'_{k−1};
  // the data need not be polynomial, so the rule is generous.
  const auto& rule = basis::gauss_legendre(2 * degree + 12);
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const double t = rule.points[q];
    const double g = at(t) - 0.5 * (1.0 - t) * start - 0.5 * (1.0 + t) * end;
    const Eigen::VectorXd legendre = basis::legendre_values(degree, t);
    for (int k = 2; k <= degree; ++k) {
      const int n = k - 1;  // (1 − t²) P'_n = n (P_{n−1} − t P_n), t inside (−1, 1)
      const double derivative = n * (legendre(n - 1) - t * legendre(n)) / (1.0 - t * t);
      a(k - 2) -= rule.weights[q] * g * std::sqrt((2.0 * k - 1.0) / 2.0) * derivative;
    }
  }
  return a;
}

namespace {

// A lift's extended space holds every cell of the problem's space: a restricted numbering gets
// its shapes here (only runs with Dirichlet data pay for them).
space::H1Space extended_with_shapes(const space::H1Space& extended) {
  return extended.holds_shapes() ? extended : extended.with_shapes();
}

}  // namespace

DirichletLift::DirichletLift(const space::H1Space& space, const PointFunction& u_d, const space::H1Space* extended)
    : extended_scalar_(extended ? std::make_unique<space::H1Space>(extended_with_shapes(*extended))
                                : std::make_unique<space::H1Space>(space.mesh(), space.cell_degrees(),
                                                                   space::DirichletDofs::kept, space.held_cells())) {
  HPC_VERIFY(&extended_scalar_->mesh() == &space.mesh(), "a lift's extended space on the space's cells");
  build(
      1, {u_d, {}}, [&](int c, int s, int) { return space.cell_shapes(c)[s].dof; }, space.n_dofs(),
      extended_scalar_->n_dofs());
}

DirichletLift::DirichletLift(const space::VectorSpace& space, const std::array<PointFunction, space::kComponents>& u_d,
                             const space::H1Space* extended)
    : extended_scalar_(extended
                           ? std::make_unique<space::H1Space>(extended_with_shapes(*extended))
                           : std::make_unique<space::H1Space>(space.scalar().mesh(), space.scalar().cell_degrees(),
                                                              space::DirichletDofs::kept, space.scalar().held_cells())),
      extended_vector_(std::make_unique<space::VectorSpace>(*extended_scalar_)) {
  HPC_VERIFY(&extended_scalar_->mesh() == &space.scalar().mesh(), "a lift's extended space on the space's cells");
  build(
      space::kComponents, u_d,
      [&](int c, int s, int comp) { return space.dof(space.scalar().cell_shapes(c)[s].dof, comp); }, space.n_dofs(),
      extended_vector_->n_dofs());
}

DirichletLift::~DirichletLift() = default;

int DirichletLift::extended_unknown(int cell, int s, int comp) const {
  const int scalar = extended_scalar_->cell_shapes(cell)[s].dof;
  return extended_vector_ ? extended_vector_->dof(scalar, comp) : scalar;
}

double DirichletLift::value(int extended_unknown) const {
  const auto it = std::lower_bound(fixed_unknowns_.begin(), fixed_unknowns_.end(), extended_unknown);
  return it != fixed_unknowns_.end() && *it == extended_unknown ? fixed_values_[it - fixed_unknowns_.begin()] : 0.0;
}

Eigen::VectorXd DirichletLift::times(const linalg::Coupling& columns) const {
  HPC_VERIFY(columns.cols() == n_extended_, "a matrix over the extended space's unknowns");
  Eigen::VectorXd out = Eigen::VectorXd::Zero(columns.rows());
  for (int row = 0; row < columns.outerSize(); ++row)
    for (linalg::Coupling::InnerIterator it(columns, row); it; ++it) {
      const auto fixed = std::lower_bound(fixed_unknowns_.begin(), fixed_unknowns_.end(), it.col());
      if (fixed != fixed_unknowns_.end() && *fixed == it.col())
        out(row) += it.value() * fixed_values_[fixed - fixed_unknowns_.begin()];
    }
  return out;
}

Eigen::VectorXd DirichletLift::values() const {
  HPC_VERIFY(every_cell_, "w of the whole space on a rank holding some cells");
  Eigen::VectorXd out = Eigen::VectorXd::Zero(n_extended_);
  for (std::size_t k = 0; k < fixed_unknowns_.size(); ++k) out(fixed_unknowns_[k]) = fixed_values_[k];
  return out;
}

void DirichletLift::build(int components, const std::array<PointFunction, space::kComponents>& u_d,
                          const UnknownOf& unknown, int n_unknowns, int n_extended) {
  const auto& mesh = extended_scalar_->mesh();
  every_cell_ = extended_scalar_->whole();
  if (every_cell_) embedding_.assign(n_unknowns, -1);
  n_extended_ = n_extended;
  n_unknowns_ = n_unknowns;
  std::map<int, double> fixed;  // w's non-zero unknowns (a shared vertex: the same value from each cell)
  for (int c = 0; c < mesh.n_cells(); ++c) {
    if (!extended_scalar_->holds(c)) continue;  // another rank's cell (the problem's space holds the same ones)
    const auto& shapes = extended_scalar_->cell_shapes(c);  // (i, j, sign) as the problem's space's
    Eigen::VectorXd local = Eigen::VectorXd::Zero(components * static_cast<Eigen::Index>(shapes.size()));
    std::array<std::array<Eigen::VectorXd, space::kComponents>, 4> edge_coefficients;  // on first use, per edge
    for (int s = 0; s < static_cast<int>(shapes.size()); ++s)
      for (int comp = 0; comp < components; ++comp) {
        const int target = extended_unknown(c, s, comp);
        if (const int own = unknown(c, s, comp); own >= 0) {
          if (every_cell_) embedding_[own] = target;
          continue;
        }
        if (!u_d[comp]) continue;
        double value = 0.0;
        if (shapes[s].role == space::ShapeRole::vertex) {
          value = u_d[comp](mesh.vertex(mesh.cell(c)[shapes[s].entity]));
        } else {
          const int edge = space::local_edge_of(shapes[s]);
          HPC_VERIFY(edge >= 0, "an interior mode is never fixed");
          auto& a = edge_coefficients[edge][comp];
          if (a.size() == 0)
            a = edge_projection(mesh, c, edge, extended_scalar_->edge_degree(mesh.cell_edge(c, edge)), u_d[comp]);
          // The shape is sign · N_k(t) on the edge, and w there must be Σ a_k N_k(t).
          value = shapes[s].sign * a(space::edge_mode_degree(shapes[s]) - 2);
        }
        local(components * s + comp) = value;
        fixed[target] = value;
      }
    if ((local.array() != 0.0).any()) cells_.push_back({c, std::move(local)});
  }
  for (const auto& [target, value] : fixed) {
    fixed_unknowns_.push_back(target);
    fixed_values_.push_back(value);
  }
  for (int i = 0; i < static_cast<int>(embedding_.size()); ++i)
    HPC_VERIFY(embedding_[i] >= 0, "every unknown has an extended one");
}

Eigen::VectorXd DirichletLift::total(const Eigen::VectorXd& u0) const {
  HPC_VERIFY(every_cell_, "u_0 + w of the whole space on a rank holding some cells");
  HPC_VERIFY(u0.size() == static_cast<Eigen::Index>(embedding_.size()), "u_0 on the problem's space");
  Eigen::VectorXd out = values();
  for (std::size_t i = 0; i < embedding_.size(); ++i) out(embedding_[i]) += u0(static_cast<Eigen::Index>(i));
  return out;
}

Eigen::VectorXd DirichletLift::restrict(const Eigen::VectorXd& extended) const {
  HPC_VERIFY(every_cell_, "a restriction of the whole space on a rank holding some cells");
  HPC_VERIFY(extended.size() == n_extended_, "a vector of the extended space");
  Eigen::VectorXd out(embedding_.size());
  for (std::size_t i = 0; i < embedding_.size(); ++i) out(static_cast<Eigen::Index>(i)) = extended(embedding_[i]);
  return out;
}

DirichletLift::LiftedLoad DirichletLift::lifted_load(const CellSystem& system, const Eigen::VectorXd& extended_load,
                                                     const LocalRows& rows, const LocalRows& extended_rows,
                                                     linalg::Distribution distribution) const {
  HPC_VERIFY(system.n_dofs() == n_unknowns_, "a cell system on the problem's space");
  HPC_VERIFY(rows.global() == extended_rows.global(), "the lift's layouts of two kinds");
  LiftedLoad out;
  std::vector<CellDof> dofs;
  // F at the problem's unknowns, and −F(w) + ½ a(w, w) (the rank's share of both when distributed,
  // summed in the serial order otherwise, so that serial energies keep their bits).
  if (rows.global()) {
    out.load = restrict(extended_load);
    out.energy_offset = -extended_load.dot(values());
  } else {
    // Cell by cell: the system's local unknowns are in the order of the lift's (shape, component).
    const int components = extended_vector_ ? space::kComponents : 1;
    out.load = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(rows.dofs().size()));
    for (int c = 0; c < extended_scalar_->mesh().n_cells(); ++c) {
      if (!rows.holds(c)) continue;
      system.cell_dofs(c, dofs);
      HPC_VERIFY(static_cast<int>(dofs.size()) == components * extended_scalar_->shape_count(c),
                 "the system's local unknowns are the lift's (shape, component) pairs");
      for (int i = 0; i < static_cast<int>(dofs.size()); ++i)
        if (dofs[i].dof >= 0)
          out.load(rows.row(dofs[i].dof)) =
              extended_load(extended_rows.row(extended_unknown(c, i / components, i % components)));
    }
    const auto& extended_dofs = extended_rows.dofs();
    for (std::size_t k = 0; k < extended_dofs.size(); ++k)
      out.energy_offset -= extended_load(static_cast<Eigen::Index>(k)) * value(extended_dofs[k]);
  }
  for (const auto& [cell, local] : cells_) {
    if (!rows.holds(cell)) continue;  // (another rank's cell)
    system.cell_dofs(cell, dofs);
    HPC_VERIFY(static_cast<Eigen::Index>(dofs.size()) == local.size(), "the lift's local layout is the system's");
    // The element matrix is in the basis of the global functions (signs included), as w's local
    // coefficients are.
    const Eigen::VectorXd a_w = system.element_matrix(cell) * local;
    out.energy_offset += 0.5 * local.dot(a_w);
    for (std::size_t i = 0; i < dofs.size(); ++i)
      if (dofs[i].dof >= 0) out.load(rows.row(dofs[i].dof)) -= a_w(static_cast<Eigen::Index>(i));
  }
  if (distribution.distributed()) sum_over_ranks(distribution.ranks, &out.energy_offset, 1);
  return out;
}

LocalRows DirichletLift::extended_rows(const LocalRows& rows) const {
  if (rows.global()) return {};
  const auto& mesh = extended_scalar_->mesh();
  std::vector<char> held(mesh.n_cells(), 0);
  std::vector<int> unknowns;
  for (int c = 0; c < mesh.n_cells(); ++c) {
    if (!rows.holds(c)) continue;
    held[c] = 1;
    for (const auto& shape : extended_scalar_->cell_shapes(c))
      if (extended_vector_)
        for (int comp = 0; comp < space::kComponents; ++comp)
          unknowns.push_back(extended_vector_->dof(shape.dof, comp));
      else
        unknowns.push_back(shape.dof);
  }
  std::sort(unknowns.begin(), unknowns.end());
  unknowns.erase(std::unique(unknowns.begin(), unknowns.end()), unknowns.end());
  return {std::move(held), std::move(unknowns)};
}

ScalarField total_field(const DirichletLift* lift, const space::H1Space& space, const Eigen::VectorXd& u0) {
  if (!lift) return {space, u0};
  return {lift->extended_scalar(), lift->total(u0)};
}

VectorField total_field(const DirichletLift* lift, const space::VectorSpace& space, const Eigen::VectorXd& u0) {
  if (!lift) return {space, u0};
  HPC_VERIFY(lift->extended_vector(), "a vector lift for a vector field");
  return {*lift->extended_vector(), lift->total(u0)};
}

}  // namespace hpcontact::assembly
