#include <algorithm>
#include <stdexcept>

#include "exercise.hpp"

namespace exercise {

std::vector<double> merge_breakpoints(const std::vector<double>& x1, const std::vector<double>& x2,
                                      double rel_tol) {
  if (x1.size() < 2 || !(x1.back() > x1.front()))
    throw std::invalid_argument("merge_breakpoints: side 1 needs two nodes and a positive length");
  if (!(rel_tol >= 0 && rel_tol < 1)) throw std::invalid_argument("merge_breakpoints: rel_tol must be in [0, 1)");
  std::vector<double> all(x1);
  all.insert(all.end(), x2.begin(), x2.end());
  std::sort(all.begin(), all.end());
  const double tol = rel_tol * (x1.back() - x1.front());
  // From the left each kept point is forced: the first point more than tol beyond the last one.
  std::vector<double> merged;
  for (double p : all)
    if (merged.empty() || p - merged.back() > tol) merged.push_back(p);
  // The largest point was dropped for the last kept one, at most tol before it: the end takes
  // its place. That point is not the first, since all.back() - all.front() >= L > tol.
  if (merged.back() != all.back()) merged.back() = all.back();
  return merged;
}

}  // namespace exercise
