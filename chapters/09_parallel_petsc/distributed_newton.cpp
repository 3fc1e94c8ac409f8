#include "distributed_newton.hpp"

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

  out.active.assign(static_cast<std::size_t>(m), false);
  for (int step = 1; step <= o.max_steps; ++step) {
    // One Newton step: w_A = 0 (rows and columns of A zeroed), one Krylov solve.
    Mat A_step;
    check(MatDuplicate(c.A, MAT_COPY_VALUES, &A_step), "MatDuplicate");
    check(VecCopy(c.r, rhs), "VecCopy");
    std::vector<PetscInt> fixed;
    PetscInt first, last;
    check(VecGetOwnershipRange(rhs, &first, &last), "VecGetOwnershipRange");
    for (int i = 0; i < m; ++i)
      if (out.active[i] && c.pivots[i] >= first && c.pivots[i] < last) fixed.push_back(c.pivots[i]);
    check(MatZeroRowsColumns(A_step, static_cast<PetscInt>(fixed.size()), fixed.data(), s.diagonal, nullptr, nullptr),
          "MatZeroRowsColumns (active set)");
    for (PetscInt d : fixed) check(VecSetValue(rhs, d, 0.0, INSERT_VALUES), "VecSetValue");
    check(VecAssemblyBegin(rhs), "VecAssemblyBegin");
    check(VecAssemblyEnd(rhs), "VecAssemblyEnd");

    KSP ksp;
    check(KSPCreate(PETSC_COMM_WORLD, &ksp), "KSPCreate");
    check(KSPSetOperators(ksp, A_step, A_step), "KSPSetOperators");
    configure(ksp, A_step, s, o.ksp_rtol);
    check(KSPSolve(ksp, rhs, v), "KSPSolve");
    KSPConvergedReason reason;
    check(KSPGetConvergedReason(ksp, &reason), "KSPGetConvergedReason");
    PetscInt iterations = 0;
    check(KSPGetIterationNumber(ksp, &iterations), "KSPGetIterationNumber");
    if (step == 1) {
      KSPType kt;
      PC pc;
      PCType pt;
      check(KSPGetType(ksp, &kt), "KSPGetType");
      check(KSPGetPC(ksp, &pc), "KSPGetPC");
      check(PCGetType(pc, &pt), "PCGetType");
      out.ksp_type = kt;
      out.pc_type = pt;
    }
    check(KSPDestroy(&ksp), "KSPDestroy");
    check(MatDestroy(&A_step), "MatDestroy");
    if (reason < 0)
      throw std::runtime_error("Newton step " + std::to_string(step) + ": the Krylov solve did not converge (" +
                               KSPConvergedReasons[reason] + " after " + std::to_string(iterations) +
                               " iterations)");
    out.ksp_iterations.push_back(static_cast<int>(iterations));
    out.steps = step;

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
    if (next == out.active) break;
    if (step == o.max_steps)
      throw std::runtime_error("semismooth Newton: the active set still changed after " + std::to_string(step) +
                               " steps");
    out.active = next;
  }
  // u = T v + g
  check(VecDuplicate(c.r, &out.u), "VecDuplicate");
  check(MatMult(c.T, v, out.u), "MatMult");
  check(VecAXPY(out.u, 1.0, c.g), "VecAXPY");
  for (Vec* x : {&v, &rhs, &Av}) check(VecDestroy(x), "VecDestroy");
}

}  // namespace chapter09
