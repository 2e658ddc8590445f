// The fields of the contact solutions, cell by cell: u_0 read at its rows, plus the lift's w at
// the extended space's dofs (the extended space has the same cells, degrees and shape order).
#include "assembly/cell_field.hpp"

#include <memory>

#include "core/error.hpp"

namespace hpcontact::assembly {

namespace {

// Each held cell's coefficients: `unknown(shape dof, component)` numbers u_0 (−1 where fixed),
// `lifted(extended dof, component)` numbers w on the lift's extended space.
CellField cell_field(const space::H1Space& space, int components, int n_unknowns, Eigen::VectorXd u0,
                     const LocalRows& rows, std::shared_ptr<const DirichletLift> lift,
                     std::function<int(int, int)> unknown, std::function<int(int, int)> lifted) {
  HPC_VERIFY(u0.size() == rows.size(n_unknowns), "a solution of another layout than its rows");
  auto values = std::make_shared<const Eigen::VectorXd>(std::move(u0));
  return {&space, components, rows,
          [&space, components, rows, lift = std::move(lift), values, unknown = std::move(unknown),
           lifted = std::move(lifted)](int cell) {
            HPC_VERIFY(rows.holds(cell), "a field read on a cell it is not known on");
            const auto& shapes = space.cell_shapes(cell);
            Eigen::MatrixXd local = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(shapes.size()), components);
            for (std::size_t s = 0; s < shapes.size(); ++s)
              for (int k = 0; k < components; ++k)
                if (const int u = unknown(shapes[s].dof, k); u >= 0) local(s, k) = (*values)(rows.row(u));
            if (lift) {
              const auto& extended = lift->extended_scalar().cell_shapes(cell);
              HPC_VERIFY(extended.size() == shapes.size(), "the lift's space has other shapes");
              for (std::size_t s = 0; s < shapes.size(); ++s)
                for (int k = 0; k < components; ++k) local(s, k) += lift->value(lifted(extended[s].dof, k));
            }
            return local;
          }};
}

}  // namespace

CellField scalar_field(const space::H1Space& space, Eigen::VectorXd u0, const LocalRows& rows,
                       std::shared_ptr<const DirichletLift> lift) {
  return cell_field(
      space, 1, space.n_dofs(), std::move(u0), rows, std::move(lift), [](int d, int) { return d; },
      [](int d, int) { return d; });
}

CellField vector_field(const space::VectorSpace& space, Eigen::VectorXd u0, const LocalRows& rows,
                       std::shared_ptr<const DirichletLift> lift) {
  HPC_VERIFY(!lift || lift->extended_vector(), "a vector lift for a vector field");
  const space::VectorSpace* extended = lift ? lift->extended_vector() : nullptr;
  return cell_field(
      space.scalar(), space::kComponents, space.n_dofs(), std::move(u0), rows, std::move(lift),
      [&space](int d, int k) { return space.dof(d, k); },
      [extended](int d, int k) { return extended ? extended->dof(d, k) : -1; });
}

}  // namespace hpcontact::assembly
