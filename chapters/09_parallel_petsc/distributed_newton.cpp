#include "distributed_newton.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

#include "common/timing/stopwatch.hpp"
#include "condensed_solver.hpp"
#include "glued_stiffness.hpp"
#include "petsc_check.hpp"

namespace chapter09 {

NewtonResult::~NewtonResult() {
  if (u != nullptr) VecDestroy(&u);
}

NewtonStart::~NewtonStart() {
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

// The rows of the active pivots this rank owns.
std::vector<PetscInt> owned_active(const DistributedCondensation& c, const std::vector<bool>& active, Vec like) {
  PetscInt first, last;
  check(VecGetOwnershipRange(like, &first, &last), "VecGetOwnershipRange");
  std::vector<PetscInt> rows;
  for (std::size_t i = 0; i < active.size(); ++i)
    if (active[i] && c.pivots[i] >= first && c.pivots[i] < last) rows.push_back(c.pivots[i]);
  return rows;
}

// v = T^{-1} (u - g) = 2 (u - g) - T (u - g) (distributed_condensation.hpp: T^{-1} = 2I - T).
void start_from(Vec u, const DistributedCondensation& c, Vec v) {
  Vec d;
  check(VecDuplicate(u, &d), "VecDuplicate");
  check(VecWAXPY(d, -1.0, c.g, u), "VecWAXPY");
  check(MatMult(c.T, d, v), "MatMult (T)");
  check(VecAXPBY(v, 2.0, -1.0, d), "VecAXPBY");
  check(VecDestroy(&d), "VecDestroy");
}

}  // namespace

void solve_contact(NewtonResult& out, const DistributedSystem& s, const DistributedCondensation& c,
                   const NewtonOptions& o, const NewtonStart* start) {
  const int m = static_cast<int>(c.pivots.size());
  PivotGather at_pivots(c.r, c.pivots);
  Vec diagonal, v, rhs, Av;
  check(VecDuplicate(c.r, &diagonal), "VecDuplicate");
  check(MatGetDiagonal(s.K, diagonal), "MatGetDiagonal");
  // c_i = A_{s_i s_i} = K_{s_i s_i}: column s_i of T is the unit vector
  const std::vector<double> c_i = at_pivots(diagonal);
  check(VecDestroy(&diagonal), "VecDestroy");
  for (Vec* x : {&v, &rhs, &Av}) check(VecDuplicate(c.r, x), "VecDuplicate");
  if (start != nullptr) start_from(start->u, c, v);
  else check(VecSet(v, 0.0), "VecSet");

  // The first active set: none (cold), every pivot (bilateral), or chapter 6's rule on the start,
  // lambda~_i + c_i w~_i > 0 with w~_i = b_i v_{s_i}
  out.active.assign(static_cast<std::size_t>(m), o.bilateral);
  if (start != nullptr && !o.bilateral) {
    const std::vector<double> v_s = at_pivots(v);
    for (int i = 0; i < m; ++i) out.active[i] = start->lambda[i] + c_i[i] / c.b[i] * v_s[i] > 0;
  }
  out.first_active = static_cast<int>(std::count(out.active.begin(), out.active.end(), true));

  // GAMG (or the command line's preconditioner), built once per level: on K, or on K glued
  // along the first active set (glued_stiffness.hpp), which the Newton steps keep
  const mortar::Stopwatch clock;
  Mat glued = nullptr;
  if (o.glue_weight > 0 && out.first_active > 0) glued = glued_stiffness(s, c, out.active, c_i, o.glue_weight);
  CondensedSolver solver(s.K, c.T, o.ksp_rtol, glued);
  if (glued != nullptr) check(MatDestroy(&glued), "MatDestroy");  // the solver's PC holds its own reference
  solver.set_up();
  out.setup_s = clock.seconds();
  out.ksp_type = solver.ksp_type();
  out.pc_type = solver.pc_type();
  const double final_rtol = solver.final_rtol(), loose_rtol = std::max(o.loose_rtol, final_rtol);

  bool tight = o.bilateral || loose_rtol <= final_rtol, repeat = false;
  for (int solve = 1; solve <= o.max_solves; ++solve) {
    // One Newton step: w_A = 0, one Krylov solve from the last v
    solver.fix(owned_active(c, out.active, rhs));
    check(VecCopy(c.r, rhs), "VecCopy");
    int iterations = 0;
    try {
      iterations = solver.solve(rhs, v, tight ? final_rtol : loose_rtol, !tight);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("Newton step " + std::to_string(out.steps + 1) + ": " + e.what());
    }
    out.ksp_iterations.push_back(iterations);
    out.tight.push_back(tight);

    // lambda = (r - A v) at the active pivots, w = v at every pivot
    solver.apply_A(v, Av);
    check(VecAYPX(Av, -1.0, c.r), "VecAYPX");
    // (B T)(i, s_i) = b_i: lambda_i = (r - A v)_{s_i} / b_i, and w_i = b_i v_{s_i}
    const std::vector<double> residual = at_pivots(Av), v_s = at_pivots(v);
    out.w.assign(static_cast<std::size_t>(m), 0.0);
    out.lambda.assign(static_cast<std::size_t>(m), 0.0);
    for (int i = 0; i < m; ++i) {
      out.w[i] = c.b[i] * v_s[i];
      if (out.active[i]) out.lambda[i] = residual[i] / c.b[i];
    }
    if (o.bilateral) {
      out.steps = 1;
      break;
    }
    // chapter 6's rule, lambda_i + c_i w_i > 0 with c_i its A_{s_i s_i} = (this A's) / b_i^2
    std::vector<bool> next(static_cast<std::size_t>(m));
    for (int i = 0; i < m; ++i) next[i] = out.lambda[i] + c_i[i] / (c.b[i] * c.b[i]) * out.w[i] > 0;
    const bool same = next == out.active;
    if (!repeat) ++out.steps;  // a new active set; a repeat is the same step solved tighter
    if (same && tight) break;
    if (solve == o.max_solves)
      throw std::runtime_error("semismooth Newton: the active set still changed after " + std::to_string(solve) +
                               " solves");
    // The set repeats after a loose solve: solve it again to the final tolerance, and check.
    tight = tight || same;  // once tight, always: a loose solve never undoes a tight one's set
    repeat = same;
    out.active = next;
  }
  out.pc_setups = solver.setups();
  out.last_active = static_cast<int>(std::count(out.active.begin(), out.active.end(), true));
  // u = T v + g
  check(VecDuplicate(c.r, &out.u), "VecDuplicate");
  check(MatMult(c.T, v, out.u), "MatMult");
  check(VecAXPY(out.u, 1.0, c.g), "VecAXPY");
  for (Vec* x : {&v, &rhs, &Av}) check(VecDestroy(x), "VecDestroy");
}

}  // namespace chapter09
