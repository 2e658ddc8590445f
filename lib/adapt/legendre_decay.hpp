// How smooth u_h is on each cell, read from the decay of its Legendre coefficients (the hp
// decision of adaptivity: raise p where they decay fast, split where they do not).
#pragma once

#include <vector>

#include "assembly/cell_field.hpp"

namespace hpcontact::adapt {

/// Per cell of `space` (the largest over the components of u_h): θ_T = exp(slope) of the least-squares line through log
/// √e_k over the shells k = max(1, p_T − 3) … p_T, where e_k is the squared L² norm (on the reference cell) of the part
/// of u_h∘Ψ_T of degree k orthogonal to lower degrees (degree max(i, j) of P_i(ξ)P_j(η) on the square, i + j on the
/// triangle). For u analytic near T, e_k decays geometrically and θ_T is its ratio (small: p pays); near a singularity
/// θ_T approaches 1 (split). A cell where u_h is constant to round-off has θ_T = 0.
std::vector<double> legendre_decay(const space::H1Space& space, const assembly::CellField& u);

}  // namespace hpcontact::adapt
