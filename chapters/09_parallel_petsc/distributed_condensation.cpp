#include "distributed_condensation.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "petsc_check.hpp"

namespace chapter09 {

DistributedCondensation::~DistributedCondensation() {
  if (T != nullptr) MatDestroy(&T);
  for (Vec* v : {&g, &r})
    if (*v != nullptr) VecDestroy(v);
}

void condense(DistributedCondensation& c, const DistributedSystem& s, const mortar::Constraints& constraints,
              const Eigen::VectorXd& G) {
  using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const RowMajor B = constraints.B;
  const PetscInt n = s.rows.size;
  const int m = static_cast<int>(B.rows());
  c.pivots.assign(constraints.pivot_dof.begin(), constraints.pivot_dof.end());
  std::vector<int> row_of(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < m; ++i) row_of[c.pivots[i]] = i;
  c.b.resize(static_cast<std::size_t>(m));  // every row's, on every rank: all take the same decisions
  for (int i = 0; i < m; ++i) c.b[i] = B.coeff(i, c.pivots[i]);

  // T: the identity on every owned row but the pivots
  c.T = create_matrix(s.rows, 8);
  check(VecDuplicate(s.f, &c.g), "VecDuplicate");
  check(VecSet(c.g, 0.0), "VecSet");
  for (PetscInt d = s.rows.first; d < s.rows.last; ++d) {
    const int i = row_of[d];
    if (i < 0) {
      check(MatSetValue(c.T, d, d, 1.0, INSERT_VALUES), "MatSetValue (T)");
      continue;
    }
    const double b = c.b[i];
    if (!(std::fabs(b) > 0)) throw std::invalid_argument("condense: row " + std::to_string(i) + " has a zero pivot");
    check(MatSetValue(c.T, d, d, 1.0, INSERT_VALUES), "MatSetValue (T)");
    for (RowMajor::InnerIterator it(B, i); it; ++it) {
      if (it.col() == d || row_of[it.col()] >= 0) continue;  // the pivot, or another row's (dual: round-off)
      check(MatSetValue(c.T, d, static_cast<PetscInt>(it.col()), -it.value() / b, INSERT_VALUES), "MatSetValue (T)");
    }
    check(VecSetValue(c.g, d, G[i] / b, INSERT_VALUES), "VecSetValue (g)");
  }
  check(MatAssemblyBegin(c.T, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin (T)");
  check(MatAssemblyEnd(c.T, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd (T)");
  check(VecAssemblyBegin(c.g), "VecAssemblyBegin");
  check(VecAssemblyEnd(c.g), "VecAssemblyEnd");

  // r = T^T (f - K g); A = T^T K T is applied, never formed (condensed_solver.hpp)
  Vec y;
  check(VecDuplicate(s.f, &y), "VecDuplicate");
  check(MatMult(s.K, c.g, y), "MatMult");
  check(VecAYPX(y, -1.0, s.f), "VecAYPX");  // y = f - K g
  check(VecDuplicate(s.f, &c.r), "VecDuplicate");
  check(MatMultTranspose(c.T, y, c.r), "MatMultTranspose");
  check(VecDestroy(&y), "VecDestroy");
}

}  // namespace chapter09
