// What the residual estimators of the scalar and the elastic contact problems share: the field's
// second derivatives at a cell's quadrature points, its traces and gradients on an edge, the
// jump of a flux across an interior edge, and the sum of the terms into the cells' indicators. Second derivatives are
// central differences of the gradient in reference coordinates (step 1e-5: truncation below 1e-9 of |∇²u_h| for the
// degrees of T_h, round-off 1e-11), which works on every cell map without its second derivatives.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "adapt/residual_estimator.hpp"
#include "assembly/cell_field.hpp"
#include "mesh/contact_boundary.hpp"
#include "space/h1_space.hpp"

namespace hpcontact::adapt {

/// The step of the central differences (header).
inline constexpr double kDifferenceStep = 1e-5;

/// The largest edge of cell c: the h_T of the indicators.
double cell_diameter(const mesh::Mesh& mesh, int c);

/// |dx/dt| of edge e at its parameter t (either direction: the speed is the same).
double edge_speed(const mesh::Mesh& mesh, int e, double t);

/// u_h at a cell's quadrature points (assembly::cell_rule with one extra point): where, the weight
/// times |det DΨ_T|, and the Hessian of each component of u_h.
struct CellSecondDerivatives {
  std::vector<mesh::Point> points;
  std::vector<double> weights;
  std::vector<std::vector<Eigen::Matrix2d>> hessians;  ///< [quadrature point][component]
};
CellSecondDerivatives cell_second_derivatives(const space::H1Space& space, const assembly::CellField& u, int c);

/// u_h and its gradient on local edge `local` of cell c at local parameters t: value (n_t ×
/// components), grad_x and grad_y (the same shape), the points (n_t × 2).
struct EdgeTrace {
  Eigen::MatrixXd value, grad_x, grad_y, points;
  /// Row k = ∇u_k at point q (components × 2).
  Eigen::MatrixXd gradient(int q) const;
};
EdgeTrace edge_trace(const space::H1Space& space, const assembly::CellField& u, int c, int local,
                     const std::vector<double>& t);

/// The normal flux of a cell's u_h across an edge: `cell`, the gradient (components × 2, as
/// EdgeTrace::gradient) and the unit normal → one value per component (∂_n u, or σ(u)n).
using NormalFlux = std::function<Eigen::VectorXd(int cell, const Eigen::MatrixXd& gradient, const mesh::Point& normal)>;

/// ½ (h_E/p_E) ‖[flux]‖²_E of interior edge e (a weight of the jump belongs in `flux`):
/// the share of each of its two cells (p_E the larger degree, p_E + 2 Gauss points).
double jump_share(const space::H1Space& space, const assembly::CellField& u, int e, const NormalFlux& flux);

/// What a boundary edge outside Γ_D adds to its cell: the flux mismatch and the contact terms.
struct BoundaryTerms {
  double flux = 0.0, contact = 0.0;
};

/// The problem-specific terms the sum over T_h asks for: the volume term of cell c, and the terms
/// of boundary edge e outside Γ_D (`trace_edge` its index in contact.edges(), −1 off Γ_C).
struct ResidualTerms {
  std::function<double(int c)> volume;
  NormalFlux flux;  ///< whose jumps across interior edges are summed
  std::function<BoundaryTerms(int e, int trace_edge)> boundary;
};

/// η_T² of every cell: its volume term, half of each of its interior edges' flux jumps, and its
/// boundary edges' terms; with the four kinds summed over T_h.
ResidualIndicators sum_indicators(const space::H1Space& space, const assembly::CellField& u,
                                  const mesh::ContactBoundary& contact, const ResidualTerms& terms);

}  // namespace hpcontact::adapt
