// Step 1 of chapter 9: the command line shared between the course and PETSc. Options with two
// dashes are the course's (OptionParser: checked, with --help); options with one dash and a
// letter (-ksp_type cg, -pc_type gamg, -log_view) are PETSc's, with the word after them as their
// value unless it is an option itself. PETSc reads its options only when it uses them, so a
// misspelt one would be silently ignored: a trial solve on a tiny matrix reads them all before
// any work, and any option still unused is refused with status 2.
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

// The PETSc options the trial solve did not read (those read only at the end, such as
// -log_view, are not counted): "" when every one was used, else their names.
std::string unused_petsc_options();

}  // namespace chapter09
