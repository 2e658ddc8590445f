// The load of the elasticity problem on [S^p(T_h)]²: body force and boundary traction.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <set>

#include "assembly/local_rows.hpp"
#include "mesh/mesh.hpp"
#include "space/vector_space.hpp"

namespace hpcontact::assembly {

using VectorFunction = std::function<Eigen::Vector2d(const mesh::Point&)>;
/// A traction t(x, n), n the outward unit normal.
using TractionFunction = std::function<Eigen::Vector2d(const mesh::Point& x, const mesh::Point& normal)>;

/// F_(j,c) = (f_c, φ_j) + ∫_{edges in `parts`} t_c φ_j ds, shape (target.size(space.n_dofs())),
/// numbered by space::VectorSpace::dof (a fixed component takes no load): the whole load or a
/// rank's share. Either function may be empty.
Eigen::VectorXd assemble_elastic_load(const space::VectorSpace& space, const VectorFunction& body_force,
                                      const std::set<mesh::BoundaryPart>& parts, const TractionFunction& traction,
                                      const LocalRows& target = {});

}  // namespace hpcontact::assembly
