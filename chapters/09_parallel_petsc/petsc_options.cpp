#include "petsc_options.hpp"

#include <petscksp.h>

#include <cctype>

#include "condensed_solver.hpp"
#include "distributed_system.hpp"
#include "petsc_check.hpp"

namespace chapter09 {

namespace {
bool is_petsc_option(const std::string& a) {
  return a.size() >= 2 && a[0] == '-' && std::isalpha(static_cast<unsigned char>(a[1]));
}

// Read by PETSc at the end of a run or by PetscInitialize, never by a solve.
bool read_outside_solves(const std::string& name) {
  // viewers and reports, read when a solve ends (-ksp_view, -ksp_converged_reason, -mat_view)
  for (const char* part : {"_view", "converged_reason", "_monitor"})
    if (name.find(part) != std::string::npos) return true;
  for (const char* prefix : {"log", "options_", "info", "malloc", "memory_", "help", "version", "history", "mpi",
                             "on_error", "fp_trap", "no_signal_handler", "check_pointer"})
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}
}  // namespace

SplitArguments split_arguments(int argc, char** argv) {
  SplitArguments s;
  s.course.push_back(argv[0]);
  s.petsc.push_back(argv[0]);
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (!is_petsc_option(a)) {
      s.course.push_back(a);
      continue;
    }
    s.petsc.push_back(a);
    if (k + 1 < argc && !is_petsc_option(argv[k + 1]) && std::string(argv[k + 1]).rfind("--", 0) != 0)
      s.petsc.push_back(argv[++k]);
  }
  return s;
}

std::vector<char*> argv_of(std::vector<std::string>& args) {
  std::vector<char*> v;
  for (std::string& a : args) v.push_back(a.data());
  v.push_back(nullptr);
  return v;
}

std::string unused_petsc_options() {
  // A trial solve configured as the chapter's solves are, on a matrix large enough for GAMG to
  // build levels below the finest (its -mg_levels_ options are read only then): the 1D
  // Laplacian (-1, 2, -1) with 400 rows per rank. Every -ksp_, -pc_ and -mg_ option that
  // applies is read; the trial's own output (a -ksp_monitor) is not shown.
  const PetscInt per_rank = 400;
  const Ownership rows{per_rank * rank(), per_rank * (rank() + 1), per_rank * ranks()};
  Mat M = create_matrix(rows, 3);
  for (PetscInt d = rows.first; d < rows.last; ++d) {
    check(MatSetValue(M, d, d, 2.0, INSERT_VALUES), "MatSetValue");
    if (d > 0) check(MatSetValue(M, d, d - 1, -1.0, INSERT_VALUES), "MatSetValue");
    if (d + 1 < rows.size) check(MatSetValue(M, d, d + 1, -1.0, INSERT_VALUES), "MatSetValue");
  }
  check(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  {
    CondensedSolver trial(M, nullptr, 1e-8);
    Vec x;
    check(MatCreateVecs(M, &x, nullptr), "MatCreateVecs");
    check(MatSetFromOptions(M), "MatSetFromOptions");
    check(VecSetFromOptions(x), "VecSetFromOptions");
    check(VecDestroy(&x), "VecDestroy");
    trial.set_up();
  }
  check(MatDestroy(&M), "MatDestroy");

  PetscInt n = 0;
  char** names = nullptr;
  char** values = nullptr;
  check(PetscOptionsLeftGet(nullptr, &n, &names, &values), "PetscOptionsLeftGet");
  std::string unused;
  for (PetscInt k = 0; k < n; ++k)
    if (!read_outside_solves(names[k])) unused += (unused.empty() ? "-" : ", -") + std::string(names[k]);
  check(PetscOptionsLeftRestore(nullptr, &n, &names, &values), "PetscOptionsLeftRestore");
  return unused;
}

}  // namespace chapter09
