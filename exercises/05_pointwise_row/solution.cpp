#include <algorithm>

#include "exercise.hpp"

namespace exercise {

Eigen::VectorXd pointwise_row(double x_a, const std::vector<double>& mortar_x) {
  Eigen::VectorXd c = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mortar_x.size()));
  // Outside the mortar side there is no mortar value to match: the zero row. The ends count
  // as covered, up to round-off.
  const double tol = 1e-12 * (mortar_x.back() - mortar_x.front());
  if (x_a < mortar_x.front() - tol || x_a > mortar_x.back() + tol) return c;
  // the element [x_e, x_{e+1}] holding x_a (the last one for the end point, the first for a
  // point a round-off below the start)
  const int last = static_cast<int>(mortar_x.size()) - 2;
  const int e = std::clamp(static_cast<int>(std::upper_bound(mortar_x.begin(), mortar_x.end(), x_a) - mortar_x.begin()) - 1, 0, last);
  const double s = (x_a - mortar_x[e]) / (mortar_x[e + 1] - mortar_x[e]);
  c[e] = 1 - s;
  c[e + 1] = s;
  return c;
}

}  // namespace exercise
