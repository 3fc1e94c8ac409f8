#include "condensed_solver.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

// PetscObjectStateGet, a developer-level call: a matrix rebuilt in place keeps its id, not its state
#include <petsc/private/petscimpl.h>

#include "petsc_check.hpp"

namespace chapter09 {

CondensedSolver::CondensedSolver(Mat K, Mat T, double rtol, Mat built_on) : K_(K), T_(T), rtol_(rtol) {
  PetscInt local = 0, global = 0;
  check(MatGetLocalSize(K, &local, nullptr), "MatGetLocalSize");
  check(MatGetSize(K, &global, nullptr), "MatGetSize");
  check(MatGetOwnershipRange(K, &first_, nullptr), "MatGetOwnershipRange");
  for (Vec* w : {&x_, &u_, &Ku_, &rho_, &z_}) check(MatCreateVecs(K, w, nullptr), "MatCreateVecs");
  check(MatCreateShell(PETSC_COMM_WORLD, local, local, global, global, this, &shell_), "MatCreateShell");
  check(MatShellSetOperation(shell_, MATOP_MULT, reinterpret_cast<void (*)(void)>(&CondensedSolver::mult)),
        "MatShellSetOperation");
  check(MatSetOption(shell_, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");

  // the preconditioner of K (or of the glued K): GAMG, then the command line's -pc_ options
  check(PCCreate(PETSC_COMM_WORLD, &inner_), "PCCreate");
  if (built_on == nullptr) built_on = K;
  check(PCSetOperators(inner_, built_on, built_on), "PCSetOperators");
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
  // The chapter's defaults, then the command line's: its -ksp_max_it, -ksp_atol and -ksp_divtol
  // hold for every solve, since solve() sets the relative tolerance only. No divergence test by
  // default: PETSc's stops a solve whose residual grows 1e5 times over its initial one, and a
  // warm start that is already nearly converged met it on round-off alone (DIVERGED_DTOL after
  // 1 iteration at E1/E2 = 1e6). The check of the true residual after each solve is the test.
  check(KSPSetTolerances(ksp_, rtol, PETSC_DEFAULT, PETSC_MAX_REAL, 10000), "KSPSetTolerances");
  check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
  check(KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE), "KSPSetInitialGuessNonzero");
}

CondensedSolver::~CondensedSolver() {
  KSPDestroy(&ksp_);
  PCDestroy(&inner_);
  MatDestroy(&shell_);
  for (Vec* w : {&x_, &u_, &Ku_, &rho_, &z_}) VecDestroy(w);
}

void CondensedSolver::set_up() {
  check(PCSetUp(inner_), "PCSetUp (the preconditioner of K or K_P)");
  // Its matrix does not change within a level, so PETSc would not rebuild anyway (it compares the
  // matrix's state); this says so, whatever a later change: the Newton steps change T's fixed rows only
  check(PCSetReusePreconditioner(inner_, PETSC_TRUE), "PCSetReusePreconditioner");
  check(KSPSetUp(ksp_), "KSPSetUp");
  ++setups_;
  built_ = fingerprint();
}

// Each object the preconditioner built, with its state: a rebuild replaces or rewrites them.
CondensedSolver::Fingerprint CondensedSolver::fingerprint() const {
  Fingerprint f;
  const auto add = [&f](PetscObject o) {
    PetscObjectId id = 0;
    PetscObjectState state = 0;
    check(PetscObjectGetId(o, &id), "PetscObjectGetId");
    check(PetscObjectStateGet(o, &state), "PetscObjectStateGet");
    f.emplace_back(id, state);
  };
  PetscBool multigrid = PETSC_FALSE, factor = PETSC_FALSE;
  check(PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(inner_), &multigrid, PCGAMG, PCMG, ""),
        "PetscObjectTypeCompareAny");
  check(PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(inner_), &factor, PCCHOLESKY, PCLU, PCICC, PCILU, ""),
        "PetscObjectTypeCompareAny");
  if (multigrid) {
    PetscInt levels = 0;
    check(PCMGGetLevels(inner_, &levels), "PCMGGetLevels");
    for (PetscInt l = 0; l < levels; ++l) {
      KSP smoother;
      Mat A, P;
      check(PCMGGetSmoother(inner_, l, &smoother), "PCMGGetSmoother");
      check(KSPGetOperators(smoother, &A, &P), "KSPGetOperators");
      add(reinterpret_cast<PetscObject>(P));
      if (l > 0) {
        Mat interpolation;
        check(PCMGGetInterpolation(inner_, l, &interpolation), "PCMGGetInterpolation");
        add(reinterpret_cast<PetscObject>(interpolation));
      }
    }
  } else if (factor) {
    Mat F;
    check(PCFactorGetMatrix(inner_, &F), "PCFactorGetMatrix");
    add(reinterpret_cast<PetscObject>(F));
  }
  return f;
}

int CondensedSolver::solve(Vec rhs, Vec v, double rtol, bool from_start) {
  zero_fixed(rhs);
  zero_fixed(v);
  // The scale of the tolerance. A loose solve (from_start) only has to tell the next active
  // set: its initial residual in PETSc's norm. The final one gives the answer: ||rhs|| in the
  // forces too (converged()).
  const double scale = from_start ? norm(residual(rhs, v)) : norm_2(rhs);
  force_ = ForceTest{nullptr, from_start ? 0.0 : rtol, scale, -1};
  void* standard;
  check(KSPConvergedDefaultCreate(&standard), "KSPConvergedDefaultCreate");
  check(KSPSetConvergenceTest(ksp_, KSPConvergedDefault, standard, nullptr), "KSPSetConvergenceTest");
  if (from_start) check(KSPConvergedDefaultSetUIRNorm(ksp_), "KSPConvergedDefaultSetUIRNorm");
  force_.standard = standard;
  check(KSPSetConvergenceTest(ksp_, &CondensedSolver::converged, this, nullptr), "KSPSetConvergenceTest");
  check(KSPSetTolerances(ksp_, rtol, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT), "KSPSetTolerances");
  const PetscErrorCode solved = KSPSolve(ksp_, rhs, v);
  KSPConvergedDefaultDestroy(standard);
  check(solved, "KSPSolve");
  if (Fingerprint now = fingerprint(); now != built_) {  // PETSc rebuilt the preconditioner
    ++setups_;
    built_ = std::move(now);
  }
  KSPConvergedReason reason;
  check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
  PetscInt iterations = 0;
  check(KSPGetIterationNumber(ksp_, &iterations), "KSPGetIterationNumber");
  // PETSc's verdict rests on the residual its recurrence carries, and on whatever the command
  // line asked (-ksp_atol, -ksp_max_it): the tolerance is checked on the true residual.
  Vec rho = residual(rhs, v);
  const double reached = (from_start ? norm(rho) : norm_2(rho)) / (scale > 0 ? scale : 1.0);
  if (!(reached <= rtol)) {
    char line[320];
    std::snprintf(line, sizeof line,
                  "the Krylov solve (%s) stopped on %s after %d iterations with a true residual of %.2e of %s, "
                  "above its tolerance %.0e",
                  ksp_type().c_str(), KSPConvergedReasons[reason], static_cast<int>(iterations), reached,
                  from_start ? "its initial one (preconditioned)" : "its right-hand side", rtol);
    throw std::runtime_error(line);
  }
  return static_cast<int>(iterations);
}

// PETSc's default test, in its norm (CG's: the preconditioned residual ||B rho||); when it is met
// on the relative tolerance, the force residual ||rho|| must meet it too. The two norms part
// when the preconditioner weighs the bodies unevenly: with E1/E2 = 1e6 CG stopped at
// ||B rho|| = 5e-14 ||B rhs|| with ||rho|| = 1e-11 ||rhs||, and the answer was 2e-8 off chapter 6's.
// A preconditioner that cannot reduce ||rho|| (-mg_levels_ksp_max_it 0) drives ||B rho|| to
// round-off: once it is 1e6 times below its tolerance, CG stops, and solve() says so.
PetscErrorCode CondensedSolver::converged(KSP ksp, PetscInt it, PetscReal rnorm, KSPConvergedReason* reason,
                                          void* context) {
  CondensedSolver* s = static_cast<CondensedSolver*>(context);
  PetscCall(KSPConvergedDefault(ksp, it, rnorm, reason, s->force_.standard));
  if (*reason != KSP_CONVERGED_RTOL || s->force_.rtol == 0) return 0;
  Vec rho;
  PetscCall(KSPBuildResidual(ksp, s->z_, s->rho_, &rho));
  PetscReal force = 0;
  PetscCall(VecNorm(rho, NORM_2, &force));
  if (force <= s->force_.rtol * s->force_.scale) return 0;
  // met in PETSc's norm, not in the forces: iterate on, unless PETSc's norm has fallen 1e6
  // times below where its test was first met
  if (s->force_.first_met < 0) s->force_.first_met = rnorm;
  if (rnorm > 1e-6 * s->force_.first_met) *reason = KSP_CONVERGED_ITERATING;
  return 0;
}

// ||x||, and ||x|| in PETSc's norm: ||B x|| (preconditioned, CG's default), or (x^T B x)^{1/2}.
double CondensedSolver::norm_2(Vec x) {
  PetscReal n = 0;
  check(VecNorm(x, NORM_2, &n), "VecNorm");
  return n;
}

double CondensedSolver::norm(Vec x) {
  KSPNormType type;
  check(KSPGetNormType(ksp_, &type), "KSPGetNormType");
  if (type == KSP_NORM_UNPRECONDITIONED) return norm_2(x);
  PC outer;
  check(KSPGetPC(ksp_, &outer), "KSPGetPC");
  check(PCApply(outer, x, z_), "PCApply");
  if (type != KSP_NORM_NATURAL) return norm_2(z_);
  PetscScalar xz = 0;
  check(VecDot(x, z_, &xz), "VecDot");
  return std::sqrt(std::fabs(xz));
}

// rhs - A_step v, computed anew (in rho_).
Vec CondensedSolver::residual(Vec rhs, Vec v) {
  check(MatMult(shell_, v, rho_), "MatMult (A_step)");
  check(VecAYPX(rho_, -1.0, rhs), "VecAYPX");
  return rho_;
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
