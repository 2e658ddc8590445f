// PetscHandle: RAII ownership of one PETSc/SLEPc object (Mat, Vec, EPS, VecScatter, ...).
#pragma once

#include <petscsys.h>

#include <utility>

namespace hpcontact {

/// Owns one PETSc object; destroys it (errors ignored: destructors must not throw) when done.
template <typename Object, PetscErrorCode (*destroy)(Object*)>
class PetscHandle {
 public:
  PetscHandle() = default;
  PetscHandle(PetscHandle&& other) noexcept : object_(std::exchange(other.object_, nullptr)) {}
  PetscHandle& operator=(PetscHandle&&) = delete;
  PetscHandle(const PetscHandle&) = delete;
  PetscHandle& operator=(const PetscHandle&) = delete;
  ~PetscHandle() {
    if (object_ != nullptr) destroy(&object_);
  }
  Object get() const { return object_; }
  Object* out() { return &object_; }

 private:
  Object object_ = nullptr;
};

}  // namespace hpcontact
