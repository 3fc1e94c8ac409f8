#include "petsc_options.hpp"

#include <petscksp.h>

#include <cctype>
#include <fstream>
#include <utility>

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

namespace {
// A trial solve configured as the chapter's solves are, on a matrix large enough for GAMG to
// build levels below the finest (its -mg_levels_ options are read only then): the 1D
// Laplacian (-1, 2, -1) with 400 rows per rank. Every -ksp_, -pc_ and -mg_ option that applies
// is read; the trial's own output (a -ksp_monitor) is not shown. Throws PetscFailure when PETSc
// refuses an option's value.
void trial_solve() {
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
  try {
    CondensedSolver trial(M, nullptr, 1e-8);
    trial.set_up();
  } catch (...) {
    MatDestroy(&M);
    throw;
  }
  check(MatDestroy(&M), "MatDestroy");
}

// The command line's options as (name, value) pairs; value "" when none followed.
std::vector<std::pair<std::string, std::string>> option_pairs(const std::vector<std::string>& petsc) {
  std::vector<std::pair<std::string, std::string>> pairs;
  for (std::size_t k = 1; k < petsc.size(); ++k) {
    if (!is_petsc_option(petsc[k])) {
      if (!pairs.empty()) pairs.back().second = petsc[k];
      continue;
    }
    pairs.emplace_back(petsc[k], "");
  }
  return pairs;
}

std::string given(const std::pair<std::string, std::string>& option) {
  return option.second.empty() ? option.first : option.first + " " + option.second;
}

// The first option that PETSc refuses on its own in a trial solve, as "-name value: reason";
// "" if none does alone (then the combination, or an -options_file, is at fault).
std::string refused_alone(const std::vector<std::pair<std::string, std::string>>& options) {
  for (const auto& option : options) {
    PetscOptions alone;
    check(PetscOptionsCreate(&alone), "PetscOptionsCreate");
    check(PetscOptionsSetValue(alone, option.first.c_str(), option.second.empty() ? nullptr : option.second.c_str()),
          "PetscOptionsSetValue");
    check(PetscOptionsPush(alone), "PetscOptionsPush");
    std::string reason;
    try {
      trial_solve();
    } catch (const PetscFailure& e) {
      reason = e.reason();
    }
    check(PetscOptionsPop(), "PetscOptionsPop");
    check(PetscOptionsDestroy(&alone), "PetscOptionsDestroy");
    if (!reason.empty()) return given(option) + ": PETSc refuses it (" + reason + ")";
  }
  return "";
}

// The options the chapter refuses, whatever their value: "" or the reason.
std::string refused_by_the_chapter() {
  const auto has = [](const char* name) {
    PetscBool set = PETSC_FALSE;
    check(PetscOptionsHasName(nullptr, nullptr, name, &set), "PetscOptionsHasName");
    return set == PETSC_TRUE;
  };
  const auto value = [](const char* name) {
    char text[64] = "";
    PetscBool set = PETSC_FALSE;
    check(PetscOptionsGetString(nullptr, nullptr, name, text, sizeof text, &set), "PetscOptionsGetString");
    return std::string(set == PETSC_TRUE ? text : "");
  };
  if (has("-ksp_rtol"))
    return "-ksp_rtol: the Krylov tolerances are the course's --ksp-rtol (the final solve) and --loose-rtol "
           "(while the active set moves), checked on the true residual";
  if (value("-ksp_type") == "preonly")
    return "-ksp_type preonly: one application of the preconditioner of K cannot solve the condensed system "
           "A v = r; use a Krylov method (cg, the default)";
  if (value("-ksp_norm_type") == "none")
    return "-ksp_norm_type none: each solve stops on its residual's norm; without one it would run -ksp_max_it "
           "iterations";
  for (const char* name : {"-mat_type", "-vec_type"})
    if (has(name))
      return std::string(name) + ": the chapter builds AIJ matrices with block size 2 (what GAMG needs to see "
                                 "the rigid-body modes) and their vectors; the type is not an option";
  return "";
}
}  // namespace

std::string petsc_options_refusal(const std::vector<std::string>& petsc) {
  const std::string chapter = refused_by_the_chapter();
  if (!chapter.empty()) return chapter;
  try {
    trial_solve();
  } catch (const PetscFailure& e) {
    const std::string alone = refused_alone(option_pairs(petsc));
    return !alone.empty() ? alone : "PETSc refuses its options (" + e.reason() + ")";
  }
  PetscInt n = 0;
  char** names = nullptr;
  char** values = nullptr;
  check(PetscOptionsLeftGet(nullptr, &n, &names, &values), "PetscOptionsLeftGet");
  std::string unused;
  for (PetscInt k = 0; k < n; ++k)
    if (!read_outside_solves(names[k])) unused += (unused.empty() ? "-" : ", -") + std::string(names[k]);
  check(PetscOptionsLeftRestore(nullptr, &n, &names, &values), "PetscOptionsLeftRestore");
  if (unused.empty()) return "";
  return "PETSc does not know or does not use " + unused +
         " (PETSc's options take one dash: -ksp_type, -pc_type, ...; the course's two)";
}

std::string unreadable_options_file(const std::vector<std::string>& petsc) {
  for (const auto& option : option_pairs(petsc)) {
    if (option.first != "-options_file") continue;
    if (option.second.empty()) return "-options_file: missing file name";
    if (!std::ifstream(option.second)) return "-options_file " + option.second + ": cannot be read";
  }
  return "";
}

}  // namespace chapter09
