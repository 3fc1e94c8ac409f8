#include <algorithm>

#include "exercise.hpp"

namespace exercise {

std::vector<double> merge_breakpoints(const std::vector<double>& x1, const std::vector<double>& x2,
                                      double rel_tol) {
  std::vector<double> all(x1);
  all.insert(all.end(), x2.begin(), x2.end());
  std::sort(all.begin(), all.end());
  const double tol = rel_tol * (x1.back() - x1.front());
  std::vector<double> merged;
  for (double p : all)
    if (merged.empty() || p - merged.back() > tol) merged.push_back(p);
  return merged;
}

}  // namespace exercise
