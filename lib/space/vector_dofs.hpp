// The numbering of [S^p(T_h)]²: the two components of each scalar dof side by side (interleaved),
// so that skeleton dofs stay before interior ones and a scalar dof's x and y unknowns are
// neighbours in the factorization.
#pragma once

#include <Eigen/Core>

namespace hpcontact::space {

inline constexpr int kComponents = 2;

/// The vector dof of component c (0: x, 1: y) of scalar dof d; -1 stays -1 (eliminated).
inline int component_dof(int scalar_dof, int component) {
  return scalar_dof < 0 ? -1 : kComponents * scalar_dof + component;
}

/// The coefficients of one component, shape (n_scalar_dofs), from interleaved ones.
inline Eigen::VectorXd component_of(const Eigen::VectorXd& u, int component) {
  return Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<kComponents>>(u.data() + component,
                                                                               u.size() / kComponents);
}

/// Interleaved coefficients from the two components' (each of shape n_scalar_dofs).
inline Eigen::VectorXd interleave(const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  Eigen::VectorXd u(kComponents * x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    u(kComponents * k) = x(k);
    u(kComponents * k + 1) = y(k);
  }
  return u;
}

}  // namespace hpcontact::space
