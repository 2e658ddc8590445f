// The largest deviation of a solution from a known one: the displacement over a body, sampled on
// a grid of points, and the contact pressure along Γ_C, for patch tests and manufactured solutions.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "assembly/cell_field.hpp"
#include "mesh/contact_boundary.hpp"
#include "mesh/mesh.hpp"
#include "space/multiplier_space.hpp"

namespace hpcontact::postprocess {

/// max |computed − exact| and max |exact| over the samples, so that deviations of several bodies
/// combine before they are made relative.
struct MaxDeviation {
  double error = 0.0, scale = 0.0;
  void add(const MaxDeviation& other);
  /// error / scale (error itself where the exact solution vanishes).
  double relative() const;
};

/// The displacement `u` (on the whole `mesh`, serial) against `exact` at the points of a
/// per_side × per_side grid over the mesh's bounding box that lie in the mesh (max norm of the
/// vector difference).
MaxDeviation displacement_deviation(const assembly::CellField& u, const mesh::Mesh& mesh,
                                    const std::function<Eigen::Vector2d(const mesh::Point&)>& exact, int per_side = 41);

/// The pressure (Legendre coefficients in `multipliers`) against `exact` at `per_segment`
/// equidistant points of every segment of T_{C,H}, ends included, x on `contact`.
MaxDeviation pressure_deviation(const space::MultiplierSpace& multipliers, const Eigen::VectorXd& pressure,
                                const mesh::ContactBoundary& contact,
                                const std::function<double(const mesh::Point&)>& exact, int per_segment = 20);

}  // namespace hpcontact::postprocess
