// Copies between Eigen vectors and sequential PETSc vectors of the same length.
#pragma once

#include <petscvec.h>

#include <Eigen/Core>
#include <algorithm>

#include "core/petsc_check.hpp"

namespace hpcontact {

/// The local entries of v.
inline Eigen::VectorXd to_eigen(Vec v) {
  PetscInt n = 0;
  HPC_PETSC_CALL(VecGetLocalSize(v, &n));
  const PetscScalar* values = nullptr;
  HPC_PETSC_CALL(VecGetArrayRead(v, &values));
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(values, static_cast<Eigen::Index>(n));
  HPC_PETSC_CALL(VecRestoreArrayRead(v, &values));
  return out;
}

/// from's entries into the local entries of `to` (of from.size()).
inline void copy_into(const Eigen::VectorXd& from, Vec to) {
  PetscScalar* values = nullptr;
  HPC_PETSC_CALL(VecGetArrayWrite(to, &values));
  std::copy_n(from.data(), from.size(), values);
  HPC_PETSC_CALL(VecRestoreArrayWrite(to, &values));
}

}  // namespace hpcontact
