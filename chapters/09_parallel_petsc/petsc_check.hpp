// PETSc's error codes, turned into the exceptions the rest of the course uses: every PETSc call
// in this chapter goes through check(), so a failure ends the program with status 1 and a
// message naming the call, like any other solver failure.
//
// PETSc's own error handler prints a trace of some 20 lines on every rank. quiet_petsc_errors()
// replaces it by one that prints nothing and keeps the first line of the failure ("Unable to
// find requested PC type bogus") for check() to put in its one line.
#pragma once

#include <petscsys.h>

#include <stdexcept>
#include <string>

namespace chapter09 {

// The message of the PETSc failure being unwound: set where it starts, cleared by check().
inline std::string& petsc_error_message() {
  static std::string message;
  return message;
}

inline PetscErrorCode keep_first_message(MPI_Comm, int, const char*, const char*, PetscErrorCode code,
                                         PetscErrorType type, const char* message, void*) {
  if (type == PETSC_ERROR_INITIAL) petsc_error_message() = message != nullptr ? message : "";
  return code;
}

inline void quiet_petsc_errors() { PetscPushErrorHandler(keep_first_message, nullptr); }

// PETSc's failure as a runtime_error: the call and PETSc's first line.
class PetscFailure : public std::runtime_error {
 public:
  PetscFailure(const char* what, std::string reason)
      : std::runtime_error(std::string("PETSc: ") + what + ": " + reason), reason_(std::move(reason)) {}
  const std::string& reason() const { return reason_; }

 private:
  std::string reason_;
};

inline void check(PetscErrorCode code, const char* what) {
  if (code == 0) return;
  std::string reason;
  reason.swap(petsc_error_message());
  if (reason.empty()) {
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    reason = text != nullptr ? text : "error";
  }
  throw PetscFailure(what, reason);
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
