#include "exercise.hpp"

namespace exercise {

std::vector<double> merge_breakpoints(const std::vector<double>& x1, const std::vector<double>& x2,
                                      double rel_tol) {
  // Your code here: refuse what the header says, then the breakpoints the three conditions
  // leave (README, "What to work out"). Side 1 alone is not the merged grid.
  (void)x2;
  (void)rel_tol;
  return x1;
}

}  // namespace exercise
