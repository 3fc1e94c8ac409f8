#include "distributed_condensation.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "petsc_check.hpp"

namespace chapter09 {

DistributedCondensation::~DistributedCondensation() {
  if (T != nullptr) MatDestroy(&T);
  for (Vec* v : {&g, &r})
    if (*v != nullptr) VecDestroy(v);
}

GlobalRows global_rows(const Part& strip, const mortar::Constraints& constraints, PetscInt num_dofs) {
  GlobalRows out;
  std::vector<Eigen::Triplet<double, PetscInt>> entries;
  for (int k = 0; k < constraints.B.outerSize(); ++k)
    for (mortar::SparseMatrix::InnerIterator it(constraints.B, k); it; ++it)
      entries.emplace_back(static_cast<PetscInt>(it.row()), strip.global(static_cast<int>(it.col())), it.value());
  out.B.resize(constraints.B.rows(), num_dofs);
  out.B.setFromTriplets(entries.begin(), entries.end());
  for (int d : constraints.pivot_dof) out.pivots.push_back(strip.global(d));
  return out;
}

void condense(DistributedCondensation& c, const DistributedSystem& s, const GlobalRows& rows, const Eigen::VectorXd& G) {
  const auto& B = rows.B;
  const int m = static_cast<int>(B.rows());
  c.pivots = rows.pivots;
  c.B = B;
  std::unordered_map<PetscInt, int> row_of;  // pivot dof -> its row
  for (int i = 0; i < m; ++i) row_of[c.pivots[i]] = i;
  const auto is_pivot = [&](PetscInt d) { return row_of.count(d) > 0; };
  c.b.resize(static_cast<std::size_t>(m));  // every row's, on every rank: all take the same decisions
  for (int i = 0; i < m; ++i) c.b[i] = B.coeff(i, c.pivots[i]);

  // T: the identity on every owned row but the pivots
  c.T = create_matrix(s.rows, 8);
  check(VecDuplicate(s.f, &c.g), "VecDuplicate");
  check(VecSet(c.g, 0.0), "VecSet");
  for (PetscInt d = s.rows.first; d < s.rows.last; ++d) {
    if (!is_pivot(d)) {
      check(MatSetValue(c.T, d, d, 1.0, INSERT_VALUES), "MatSetValue (T)");
      continue;
    }
    const int i = row_of.at(d);
    const double b = c.b[i];
    if (!(std::fabs(b) > 0)) throw std::invalid_argument("condense: row " + std::to_string(i) + " has a zero pivot");
    check(MatSetValue(c.T, d, d, 1.0, INSERT_VALUES), "MatSetValue (T)");
    for (GlobalRows::Matrix::InnerIterator it(B, i); it; ++it) {
      if (it.col() == d || is_pivot(it.col())) continue;  // the pivot, or another row's (dual: round-off)
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
