#include "glued_stiffness.hpp"

#include <unordered_set>

#include "petsc_check.hpp"

namespace chapter09 {

namespace {
// sum_{i in P} kappa_i B_i^T B_i alone, on the rows of K: a few dense blocks along Gamma_c, each
// added by the rank that owns its pivot. Preallocated empty: the few insertions reallocate a
// matrix that holds nothing else, which is cheap.
Mat glue(const DistributedSystem& s, const DistributedCondensation& c, const std::vector<bool>& active,
         const std::vector<double>& K_ss, double alpha) {
  Mat glue;
  check(MatCreateAIJ(PETSC_COMM_WORLD, s.rows.local(), s.rows.local(), s.rows.size, s.rows.size, 0, nullptr, 0,
                     nullptr, &glue),
        "MatCreateAIJ");
  check(MatSetOption(glue, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE), "MatSetOption");
  const std::unordered_set<PetscInt> pivots(c.pivots.begin(), c.pivots.end());
  std::vector<PetscInt> columns;
  std::vector<double> values, block;
  for (std::size_t i = 0; i < active.size(); ++i) {
    if (!active[i] || !s.rows.owns(c.pivots[i])) continue;
    // row i of B: b_i at s_i, and the mortar side's entries (another pivot's column holds
    // round-off only, as in condense())
    columns.assign(1, c.pivots[i]);
    values.assign(1, c.b[i]);
    for (DistributedCondensation::RowsB::InnerIterator it(c.B, static_cast<PetscInt>(i)); it; ++it) {
      if (pivots.count(it.col()) > 0) continue;
      columns.push_back(it.col());
      values.push_back(it.value());
    }
    const double kappa = alpha * K_ss[i] / (c.b[i] * c.b[i]);
    const std::size_t n = columns.size();
    block.resize(n * n);
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b) block[a * n + b] = kappa * values[a] * values[b];
    const PetscInt size = static_cast<PetscInt>(n);
    check(MatSetValues(glue, size, columns.data(), size, columns.data(), block.data(), ADD_VALUES), "MatSetValues");
  }
  check(MatAssemblyBegin(glue, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(glue, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  return glue;
}
}  // namespace

Mat glued_stiffness(const DistributedSystem& s, const DistributedCondensation& c, const std::vector<bool>& active,
                    const std::vector<double>& K_ss, double alpha) {
  Mat added = glue(s, c, active, K_ss, alpha), K_P;
  check(MatDuplicate(s.K, MAT_COPY_VALUES, &K_P), "MatDuplicate");
  check(MatAXPY(K_P, 1.0, added, DIFFERENT_NONZERO_PATTERN), "MatAXPY (K + the glue)");
  check(MatDestroy(&added), "MatDestroy");
  check(MatSetOption(K_P, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  MatNullSpace modes;
  check(MatGetNearNullSpace(s.K, &modes), "MatGetNearNullSpace");
  check(MatSetNearNullSpace(K_P, modes), "MatSetNearNullSpace");
  return K_P;
}

}  // namespace chapter09
