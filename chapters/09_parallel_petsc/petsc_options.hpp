// Step 1 of chapter 9: the command line shared between the course and PETSc. Options with two
// dashes are the course's (OptionParser: checked, with --help); options with one dash and a
// letter (-ksp_type cg, -pc_type gamg, -log_view) are PETSc's, with the word after them as their
// value unless it is an option itself. PETSc reads its options only when it uses them, so a
// misspelt one would be silently ignored: a trial solve on a tiny matrix reads them all before
// any work, and any option still unused, or whose value PETSc refuses, is refused with status 2.
#pragma once

#include <string>
#include <vector>

namespace chapter09 {

struct SplitArguments {
  std::vector<std::string> course;  // argv[0] and the course's options
  std::vector<std::string> petsc;   // argv[0] and PETSc's options
};
SplitArguments split_arguments(int argc, char** argv);

// Argument vectors as main() receives them, pointing into `args` (which must outlive them).
std::vector<char*> argv_of(std::vector<std::string>& args);

// "" when the PETSc options of `petsc` (argv[0] first, as split_arguments gives them) can run
// the chapter's solves, else one line naming the option at fault, before any work:
//   - options the chapter refuses: -ksp_rtol (the tolerances are the course's --ksp-rtol and
//     --loose-rtol, which it checks on the true residual), -ksp_type preonly and
//     -ksp_norm_type none (no Krylov method, or nothing to stop on), -mat_type and -vec_type
//     (the matrices are AIJ with block size 2, what GAMG needs);
//   - an option whose value PETSc refuses in the trial solve (-pc_type bogus, -ksp_divtol abc);
//   - an option the trial solve did not read (those read only at the end, such as -log_view,
//     are not counted).
std::string petsc_options_refusal(const std::vector<std::string>& petsc);

// "" when every -options_file of `petsc` can be read, else the one line saying which cannot
// (checked before PETSc starts, which would otherwise stop with its own trace).
std::string unreadable_options_file(const std::vector<std::string>& petsc);

}  // namespace chapter09
