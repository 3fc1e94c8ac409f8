#include "condensed_solver.hpp"

#include <stdexcept>

#include "petsc_check.hpp"

namespace chapter09 {

CondensedSolver::CondensedSolver(Mat K, Mat T, double rtol) : K_(K), T_(T) {
  PetscInt local = 0, global = 0;
  check(MatGetLocalSize(K, &local, nullptr), "MatGetLocalSize");
  check(MatGetSize(K, &global, nullptr), "MatGetSize");
  check(MatGetOwnershipRange(K, &first_, nullptr), "MatGetOwnershipRange");
  for (Vec* w : {&x_, &u_, &Ku_}) check(MatCreateVecs(K, w, nullptr), "MatCreateVecs");
  check(MatCreateShell(PETSC_COMM_WORLD, local, local, global, global, this, &shell_), "MatCreateShell");
  check(MatShellSetOperation(shell_, MATOP_MULT, reinterpret_cast<void (*)(void)>(&CondensedSolver::mult)),
        "MatShellSetOperation");
  check(MatSetOption(shell_, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");

  // the preconditioner of K: GAMG, then the command line's -pc_ options
  check(PCCreate(PETSC_COMM_WORLD, &inner_), "PCCreate");
  check(PCSetOperators(inner_, K, K), "PCSetOperators");
  check(PCSetType(inner_, PCGAMG), "PCSetType");
  check(PCSetFromOptions(inner_), "PCSetFromOptions");

  // CG on A_step, preconditioned by the shell around it, then the command line's -ksp_ options;
  // the outer preconditioner has its own prefix, so that -pc_type reaches the inner one only
  check(KSPCreate(PETSC_COMM_WORLD, &ksp_), "KSPCreate");
  check(KSPSetOperators(ksp_, shell_, shell_), "KSPSetOperators");
  check(KSPSetType(ksp_, KSPCG), "KSPSetType");
  PC outer;
  check(KSPGetPC(ksp_, &outer), "KSPGetPC");
  check(PCSetOptionsPrefix(outer, "condensed_"), "PCSetOptionsPrefix");
  check(PCSetType(outer, PCSHELL), "PCSetType");
  check(PCShellSetContext(outer, this), "PCShellSetContext");
  check(PCShellSetApply(outer, &CondensedSolver::precondition), "PCShellSetApply");
  check(KSPSetTolerances(ksp_, rtol, PETSC_DEFAULT, PETSC_DEFAULT, 10000), "KSPSetTolerances");
  check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
  check(KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE), "KSPSetInitialGuessNonzero");
  PetscReal configured;
  check(KSPGetTolerances(ksp_, &configured, nullptr, nullptr, nullptr), "KSPGetTolerances");
  rtol_ = configured;
}

CondensedSolver::~CondensedSolver() {
  KSPDestroy(&ksp_);
  PCDestroy(&inner_);
  MatDestroy(&shell_);
  for (Vec* w : {&x_, &u_, &Ku_}) VecDestroy(w);
}

void CondensedSolver::set_up() {
  check(PCSetUp(inner_), "PCSetUp (the preconditioner of K)");
  check(KSPSetUp(ksp_), "KSPSetUp");
}

int CondensedSolver::solve(Vec rhs, Vec v, double rtol, bool from_start) {
  zero_fixed(rhs);
  zero_fixed(v);
  // a fresh convergence test each time: relative to ||B rhs||, or to the initial residual
  void* test;
  check(KSPConvergedDefaultCreate(&test), "KSPConvergedDefaultCreate");
  check(KSPSetConvergenceTest(ksp_, KSPConvergedDefault, test, KSPConvergedDefaultDestroy), "KSPSetConvergenceTest");
  if (from_start) check(KSPConvergedDefaultSetUIRNorm(ksp_), "KSPConvergedDefaultSetUIRNorm");
  check(KSPSetTolerances(ksp_, rtol, PETSC_DEFAULT, PETSC_DEFAULT, 10000), "KSPSetTolerances");
  check(KSPSolve(ksp_, rhs, v), "KSPSolve");
  KSPConvergedReason reason;
  check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
  PetscInt iterations = 0;
  check(KSPGetIterationNumber(ksp_, &iterations), "KSPGetIterationNumber");
  if (reason < 0)
    throw std::runtime_error(std::string("the Krylov solve did not converge (") + KSPConvergedReasons[reason] +
                             " after " + std::to_string(iterations) + " iterations)");
  return static_cast<int>(iterations);
}

// y = T x, T^T x, T^{-1} x = 2x - T x or T^{-T} x = 2x - T^T x; T = nullptr is the identity.
void CondensedSolver::apply_T(Vec x, Vec y, bool transpose, bool inverse) {
  if (T_ == nullptr) {
    check(VecCopy(x, y), "VecCopy");
    return;
  }
  check(transpose ? MatMultTranspose(T_, x, y) : MatMult(T_, x, y), "MatMult (T)");
  if (inverse) check(VecAXPBY(y, 2.0, -1.0, x), "VecAXPBY");  // y = 2x - y
}

void CondensedSolver::apply_A(Vec x, Vec y) {
  apply_T(x, u_, false, false);
  check(MatMult(K_, u_, Ku_), "MatMult (K)");
  apply_T(Ku_, y, true, false);
}

void CondensedSolver::zero_fixed(Vec x) const {
  PetscScalar* a;
  check(VecGetArray(x, &a), "VecGetArray");
  for (PetscInt d : fixed_) a[d - first_] = 0;
  check(VecRestoreArray(x, &a), "VecRestoreArray");
}

void CondensedSolver::copy_fixed(Vec from, Vec to) const {
  const PetscScalar* f;
  PetscScalar* t;
  check(VecGetArrayRead(from, &f), "VecGetArrayRead");
  check(VecGetArray(to, &t), "VecGetArray");
  for (PetscInt d : fixed_) t[d - first_] = f[d - first_];
  check(VecRestoreArray(to, &t), "VecRestoreArray");
  check(VecRestoreArrayRead(from, &f), "VecRestoreArrayRead");
}

// A_step x = Pi A Pi x + (I - Pi) x
PetscErrorCode CondensedSolver::mult(Mat shell, Vec x, Vec y) {
  CondensedSolver* s = nullptr;
  PetscCall(MatShellGetContext(shell, &s));
  try {
    PetscCall(VecCopy(x, s->x_));
    s->zero_fixed(s->x_);
    s->apply_A(s->x_, y);
    s->copy_fixed(x, y);
  } catch (const std::exception&) {
    return PETSC_ERR_LIB;
  }
  return 0;
}

// M_step^{-1} r = Pi T^{-1} M^{-1} T^{-T} Pi r + (I - Pi) r
PetscErrorCode CondensedSolver::precondition(PC pc, Vec r, Vec z) {
  CondensedSolver* s = nullptr;
  PetscCall(PCShellGetContext(pc, &s));
  try {
    PetscCall(VecCopy(r, s->x_));
    s->zero_fixed(s->x_);
    s->apply_T(s->x_, s->u_, true, true);
    PetscCall(PCApply(s->inner_, s->u_, s->Ku_));
    s->apply_T(s->Ku_, z, false, true);
    s->zero_fixed(z);
    s->copy_fixed(r, z);
  } catch (const std::exception&) {
    return PETSC_ERR_LIB;
  }
  return 0;
}

std::string CondensedSolver::ksp_type() const {
  KSPType t;
  check(KSPGetType(ksp_, &t), "KSPGetType");
  return t;
}

std::string CondensedSolver::pc_type() const {
  PCType t;
  check(PCGetType(inner_, &t), "PCGetType");
  return t;
}

}  // namespace chapter09
