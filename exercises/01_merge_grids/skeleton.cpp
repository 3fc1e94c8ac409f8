#include "exercise.hpp"

namespace exercise {

std::vector<double> merge_breakpoints(const std::vector<double>& x1, const std::vector<double>& x2,
                                      double rel_tol) {
  // Your code here: put both lists together, sort, and keep a point only if it is more than
  // rel_tol * L beyond the last point kept.
  (void)x2;
  (void)rel_tol;
  return x1;
}

}  // namespace exercise
