#include "distributed_newton.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "petsc_check.hpp"

namespace chapter09 {

NewtonResult::~NewtonResult() {
  if (u != nullptr) VecDestroy(&u);
}

namespace {
// The values of x at the pivots, on every rank.
class PivotGather {
 public:
  PivotGather(Vec like, const std::vector<PetscInt>& pivots) : m_(static_cast<PetscInt>(pivots.size())) {
    check(ISCreateGeneral(PETSC_COMM_SELF, m_, pivots.data(), PETSC_COPY_VALUES, &is_), "ISCreateGeneral");
    check(VecCreateSeq(PETSC_COMM_SELF, m_, &local_), "VecCreateSeq");
    check(VecScatterCreate(like, is_, local_, nullptr, &scatter_), "VecScatterCreate");
  }
  ~PivotGather() {
    VecScatterDestroy(&scatter_);
    VecDestroy(&local_);
    ISDestroy(&is_);
  }
  std::vector<double> operator()(Vec x) {
    check(VecScatterBegin(scatter_, x, local_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
    check(VecScatterEnd(scatter_, x, local_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
    const PetscScalar* a;
    check(VecGetArrayRead(local_, &a), "VecGetArrayRead");
    std::vector<double> values(a, a + m_);
    check(VecRestoreArrayRead(local_, &a), "VecRestoreArrayRead");
    return values;
  }

 private:
  PetscInt m_;
  IS is_ = nullptr;
  Vec local_ = nullptr;
  VecScatter scatter_ = nullptr;
};

// The solver of configure_krylov_solver, with the rigid-body modes of the bodies attached to A.
void configure(KSP ksp, Mat A, const DistributedSystem& s, double rtol) {
  MatNullSpace modes;
  check(MatNullSpaceCreateRigidBody(s.coordinates, &modes), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(A, modes), "MatSetNearNullSpace");
  check(MatNullSpaceDestroy(&modes), "MatNullSpaceDestroy");
  configure_krylov_solver(ksp, rtol);
}
}  // namespace

void configure_krylov_solver(KSP ksp, double rtol) {
  check(KSPSetType(ksp, KSPCG), "KSPSetType");
  PC pc;
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PCSetType(pc, PCGAMG), "PCSetType");
  check(KSPSetTolerances(ksp, rtol, PETSC_DEFAULT, PETSC_DEFAULT, 10000), "KSPSetTolerances");
  check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
}

namespace {
// The rows of the active pivots this rank owns.
std::vector<PetscInt> owned_active(const DistributedCondensation& c, const std::vector<bool>& active, Vec like) {
  PetscInt first, last;
  check(VecGetOwnershipRange(like, &first, &last), "VecGetOwnershipRange");
  std::vector<PetscInt> rows;
  for (std::size_t i = 0; i < active.size(); ++i)
    if (active[i] && c.pivots[i] >= first && c.pivots[i] < last) rows.push_back(c.pivots[i]);
  return rows;
}

// Set x to 0 on the given rows (owned ones).
void zero_rows(Vec x, const std::vector<PetscInt>& rows) {
  for (PetscInt d : rows) check(VecSetValue(x, d, 0.0, INSERT_VALUES), "VecSetValue");
  check(VecAssemblyBegin(x), "VecAssemblyBegin");
  check(VecAssemblyEnd(x), "VecAssemblyEnd");
}
}  // namespace

void solve_contact(NewtonResult& out, const DistributedSystem& s, const DistributedCondensation& c,
                   const NewtonOptions& o) {
  const int m = static_cast<int>(c.pivots.size());
  PivotGather at_pivots(c.r, c.pivots);
  Vec diagonal, v, rhs, Av;
  check(VecDuplicate(c.r, &diagonal), "VecDuplicate");
  check(MatGetDiagonal(c.A, diagonal), "MatGetDiagonal");
  const std::vector<double> c_i = at_pivots(diagonal);  // c_i = A_{s_i s_i}
  check(VecDestroy(&diagonal), "VecDestroy");
  for (Vec* x : {&v, &rhs, &Av}) check(VecDuplicate(c.r, x), "VecDuplicate");
  check(VecSet(v, 0.0), "VecSet");

  // One matrix for every step (A with the active rows and columns zeroed), one solver.
  Mat A_step;
  check(MatDuplicate(c.A, MAT_COPY_VALUES, &A_step), "MatDuplicate");
  KSP ksp;
  check(KSPCreate(PETSC_COMM_WORLD, &ksp), "KSPCreate");
  check(KSPSetOperators(ksp, A_step, A_step), "KSPSetOperators");
  configure(ksp, A_step, s, o.ksp_rtol);
  PetscReal configured_rtol;
  check(KSPGetTolerances(ksp, &configured_rtol, nullptr, nullptr, nullptr), "KSPGetTolerances");
  // the command line's -ksp_rtol, if any, is the final tolerance
  const double final_rtol = configured_rtol, loose_rtol = std::max(o.loose_rtol, final_rtol);
  check(KSPSetInitialGuessNonzero(ksp, PETSC_TRUE), "KSPSetInitialGuessNonzero");
  {
    KSPType kt;
    PC pc;
    PCType pt;
    check(KSPGetType(ksp, &kt), "KSPGetType");
    check(KSPGetPC(ksp, &pc), "KSPGetPC");
    check(PCGetType(pc, &pt), "PCGetType");
    out.ksp_type = kt;
    out.pc_type = pt;
  }

  out.active.assign(static_cast<std::size_t>(m), false);
  bool tight = loose_rtol <= final_rtol, repeat = false;
  for (int solve = 1; solve <= o.max_steps; ++solve) {
    // One Newton step: w_A = 0 (rows and columns of A zeroed), one Krylov solve from the last v.
    const std::vector<PetscInt> fixed = owned_active(c, out.active, rhs);
    if (solve > 1) check(MatCopy(c.A, A_step, SAME_NONZERO_PATTERN), "MatCopy");
    check(MatZeroRowsColumns(A_step, static_cast<PetscInt>(fixed.size()), fixed.data(), s.diagonal, nullptr, nullptr),
          "MatZeroRowsColumns (active set)");
    check(VecCopy(c.r, rhs), "VecCopy");
    zero_rows(rhs, fixed);
    zero_rows(v, fixed);
    // GAMG's hierarchy is built once, on the first step's A (no pivot fixed), and kept; or
    // built again from scratch (a rebuild on top of the old one keeps stale smoother estimates)
    if (solve > 1 && o.reuse_preconditioner) {
      check(KSPSetReusePreconditioner(ksp, PETSC_TRUE), "KSPSetReusePreconditioner");
    } else if (solve > 1) {
      check(KSPReset(ksp), "KSPReset");
      check(KSPSetOperators(ksp, A_step, A_step), "KSPSetOperators");
    }
    check(KSPSetTolerances(ksp, tight ? final_rtol : loose_rtol, PETSC_DEFAULT, PETSC_DEFAULT, 10000),
          "KSPSetTolerances");
    // A loose solve reduces its own initial residual (the last v is close); the final one
    // reaches rtol ||B r||, B the preconditioner, as every chapter-6 comparison assumes.
    void* test;
    check(KSPConvergedDefaultCreate(&test), "KSPConvergedDefaultCreate");
    check(KSPSetConvergenceTest(ksp, KSPConvergedDefault, test, KSPConvergedDefaultDestroy), "KSPSetConvergenceTest");
    if (!tight) check(KSPConvergedDefaultSetUIRNorm(ksp), "KSPConvergedDefaultSetUIRNorm");
    check(KSPSolve(ksp, rhs, v), "KSPSolve");
    KSPConvergedReason reason;
    check(KSPGetConvergedReason(ksp, &reason), "KSPGetConvergedReason");
    PetscInt iterations = 0;
    check(KSPGetIterationNumber(ksp, &iterations), "KSPGetIterationNumber");
    if (reason < 0)
      throw std::runtime_error("Newton step " + std::to_string(out.steps + 1) +
                               ": the Krylov solve did not converge (" + KSPConvergedReasons[reason] + " after " +
                               std::to_string(iterations) + " iterations)");
    out.ksp_iterations.push_back(static_cast<int>(iterations));
    out.tight.push_back(tight);

    // lambda = (r - A v) at the active pivots, w = v at every pivot
    check(MatMult(c.A, v, Av), "MatMult");
    check(VecAYPX(Av, -1.0, c.r), "VecAYPX");
    // (B T)(i, s_i) = b_i: lambda_i = (r - A v)_{s_i} / b_i, and w_i = b_i v_{s_i}
    const std::vector<double> residual = at_pivots(Av), v_s = at_pivots(v);
    out.w.assign(static_cast<std::size_t>(m), 0.0);
    out.lambda.assign(static_cast<std::size_t>(m), 0.0);
    for (int i = 0; i < m; ++i) {
      out.w[i] = c.b[i] * v_s[i];
      if (out.active[i]) out.lambda[i] = residual[i] / c.b[i];
    }
    // chapter 6's rule, lambda_i + c_i w_i > 0 with c_i its A_{s_i s_i} = (this A's) / b_i^2
    std::vector<bool> next(static_cast<std::size_t>(m));
    for (int i = 0; i < m; ++i) next[i] = out.lambda[i] + c_i[i] / (c.b[i] * c.b[i]) * out.w[i] > 0;
    const bool same = next == out.active;
    if (!repeat) ++out.steps;  // a new active set; a repeat is the same step solved tighter
    if (same && tight) break;
    if (solve == o.max_steps)
      throw std::runtime_error("semismooth Newton: the active set still changed after " + std::to_string(solve) +
                               " solves");
    // The set repeats after a loose solve: solve it again to the final tolerance, and check.
    tight = tight || same;  // once tight, always: a loose solve never undoes a tight one's set
    repeat = same;
    out.active = next;
  }
  check(KSPDestroy(&ksp), "KSPDestroy");
  check(MatDestroy(&A_step), "MatDestroy");
  // u = T v + g
  check(VecDuplicate(c.r, &out.u), "VecDuplicate");
  check(MatMult(c.T, v, out.u), "MatMult");
  check(VecAXPY(out.u, 1.0, c.g), "VecAXPY");
  for (Vec* x : {&v, &rhs, &Av}) check(VecDestroy(x), "VecDestroy");
}

}  // namespace chapter09
