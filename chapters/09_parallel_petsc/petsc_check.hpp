// PETSc's error codes, turned into the exceptions the rest of the course uses: every PETSc call
// in this chapter goes through check(), so a failure ends the program with status 1 and a
// message naming the call, like any other solver failure.
#pragma once

#include <petscsys.h>

#include <stdexcept>
#include <string>

namespace chapter09 {

inline void check(PetscErrorCode code, const char* what) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw std::runtime_error(std::string("PETSc: ") + what + ": " + (text != nullptr ? text : "error"));
}

// The rank and the number of ranks of PETSC_COMM_WORLD.
inline int rank() {
  int r = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &r);
  return r;
}
inline int ranks() {
  int n = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &n);
  return n;
}

}  // namespace chapter09
